#pragma once
// What a result file records about the build that made it (docs/measurement.md).
#include <string_view>

namespace lumina::gi {

// The git commit the binary was built from, "-dirty" appended when tracked files differed
// from it; "unknown" outside a git checkout.
std::string_view gitCommit();

} // namespace lumina::gi
