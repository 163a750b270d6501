#include "gi/bench/bench_matrix.h"

#include <algorithm>
#include <stdexcept>

namespace lumina::gi {

std::vector<std::string> BenchMatrix::realTimeTechniques() const {
    std::vector<std::string> realTime;
    std::ranges::copy_if(techniques, std::back_inserter(realTime),
                         [](const std::string& t) { return t != "pathtracer"; });
    return realTime;
}

bool BenchMatrix::hasPathTracer() const {
    return std::ranges::find(techniques, "pathtracer") != techniques.end();
}

std::string BenchMatrix::timeBase() const {
    for (const char* base : {"lumen", "direct"}) {
        if (std::ranges::find(techniques, base) != techniques.end()) {
            return base;
        }
    }
    return {};
}

size_t BenchMatrix::rowCount() const {
    return scenes * (realTimeTechniques().size() * presets + (hasPathTracer() ? budgets : 0));
}

size_t BenchMatrix::realTimeRow(size_t scene, const std::string& technique, size_t preset) const {
    const std::vector<std::string> realTime = realTimeTechniques();
    const auto found = std::ranges::find(realTime, technique);
    if (found == realTime.end()) {
        throw std::logic_error("bench matrix: no technique '" + technique + "'");
    }
    return scene * (rowCount() / scenes) + size_t(found - realTime.begin()) * presets + preset;
}

size_t BenchMatrix::pathTracerRow(size_t scene, size_t budget) const {
    return scene * (rowCount() / scenes) + realTimeTechniques().size() * presets + budget;
}

std::vector<BenchUnit> benchUnits(const BenchMatrix& matrix) {
    std::vector<BenchUnit> units;
    const std::string base = matrix.timeBase();
    for (size_t scene = 0; scene < matrix.scenes; ++scene) {
        for (const std::string& technique : matrix.realTimeTechniques()) {
            units.push_back({scene, technique, matrix.hasPathTracer() && technique == base});
        }
        if (matrix.hasPathTracer() && base.empty()) {
            units.push_back({scene, "pathtracer", true});
        }
    }
    return units;
}

} // namespace lumina::gi
