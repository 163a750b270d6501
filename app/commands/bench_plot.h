#pragma once
// The bench's plot of error against frame time (scripts/plot_bench.py, python3-matplotlib),
// made by `lumina bench` and by `lumina merge` of bench shards.
#include <filesystem>

namespace lumina::app {

// False, with a note on stderr, when the script or matplotlib is missing.
bool makeBenchPlot(const std::filesystem::path& csv, const std::filesystem::path& png);

} // namespace lumina::app
