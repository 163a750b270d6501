#pragma once
// Where Lumina keeps what it can rebuild (mesh SDFs, path-traced references): one root,
// one folder per kind of data below it.
#include <filesystem>

namespace lumina::gi {

// $LUMINA_CACHE_DIR, else $XDG_CACHE_HOME/lumina, else ~/.cache/lumina (%LOCALAPPDATA%\lumina
// on Windows), else <temp>/lumina.
std::filesystem::path cacheRoot();

} // namespace lumina::gi
