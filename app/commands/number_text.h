#pragma once
// A number for the commands' printed reports: `digits` significant digits, printf's %g.
#include <cstdio>
#include <string>

namespace lumina::app {

inline std::string numberText(double value, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

} // namespace lumina::app
