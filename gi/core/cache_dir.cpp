#include "gi/core/cache_dir.h"

#include <cstdlib>

namespace lumina::gi {

namespace {

std::filesystem::path envPath(const char* name) {
    const char* value = std::getenv(name);
    return value && *value ? std::filesystem::path(value) : std::filesystem::path();
}

} // namespace

std::filesystem::path cacheRoot() {
    if (auto dir = envPath("LUMINA_CACHE_DIR"); !dir.empty()) {
        return dir;
    }
    if (auto dir = envPath("XDG_CACHE_HOME"); !dir.empty()) {
        return dir / "lumina";
    }
#ifdef _WIN32
    if (auto dir = envPath("LOCALAPPDATA"); !dir.empty()) {
        return dir / "lumina";
    }
#endif
    if (auto dir = envPath("HOME"); !dir.empty()) {
        return dir / ".cache" / "lumina";
    }
    return std::filesystem::temp_directory_path() / "lumina";
}

} // namespace lumina::gi
