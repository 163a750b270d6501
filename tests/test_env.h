#pragma once
// Setting and clearing environment variables in tests, on POSIX and Windows alike (Windows has
// no setenv/unsetenv; an empty value given to _putenv_s removes the variable).
#include <cstdlib>
#include <string>

namespace lumina::testing {

// An empty value removes the variable.
inline void setEnv(const char* name, const std::string& value) {
#ifdef _WIN32
    _putenv_s(name, value.c_str());
#else
    if (value.empty()) {
        ::unsetenv(name);
    } else {
        ::setenv(name, value.c_str(), 1);
    }
#endif
}

inline void unsetEnv(const char* name) {
    setEnv(name, "");
}

} // namespace lumina::testing
