#include "app/commands/bench_plot.h"

#include "gi/scene/builtin_scenes.h"

#include <cstdlib>
#include <iostream>
#include <string>

namespace lumina::app {

namespace {

// scripts/plot_bench.py from the source tree the built-in scenes come from.
std::filesystem::path plotScript() {
    if (const auto scenes = scene::findScenesDirectory()) {
        return scenes->parent_path() / "scripts" / "plot_bench.py";
    }
    return {};
}

// Debian's python3 first: python3-matplotlib is installed for it, whatever else PATH holds.
std::string pythonInterpreter() {
    if (const char* chosen = std::getenv("LUMINA_PYTHON"); chosen && *chosen) {
        return chosen;
    }
    return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

} // namespace

bool makeBenchPlot(const std::filesystem::path& csv, const std::filesystem::path& png) {
    const std::filesystem::path script = plotScript();
    if (script.empty() || !std::filesystem::exists(script)) {
        std::cerr << "bench: note: no plot, scripts/plot_bench.py not found (set LUMINA_SOURCE_DIR)\n";
        return false;
    }
    const std::string command = "\"" + pythonInterpreter() + "\" \"" + script.string() + "\" \"" +
                                csv.string() + "\" \"" + png.string() + "\"";
    if (std::system(command.c_str()) != 0) {
        std::cerr << "bench: note: the plot failed (it needs python3-matplotlib; LUMINA_PYTHON picks the "
                     "interpreter): "
                  << command << '\n';
        return false;
    }
    return true;
}

} // namespace lumina::app
