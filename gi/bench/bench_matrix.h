#pragma once
// The rows `lumina bench` writes, in order, and the units a shard of it runs (docs/batch.md).
// One run writes, per scene: each real-time technique at each preset, then the path tracer at
// each budget. A unit is one scene and one real-time technique; the path tracer goes with the
// technique whose frame time its budgets multiply (lumen, else direct), so a shard measures
// that base itself and every row means what it means in one run.
#include <cstddef>
#include <string>
#include <vector>

namespace lumina::gi {

struct BenchMatrix {
    size_t scenes = 0;
    std::vector<std::string> techniques; // as given, "pathtracer" among them or not
    size_t presets = 0;
    size_t budgets = 0;

    std::vector<std::string> realTimeTechniques() const;
    bool hasPathTracer() const;
    // lumen when it runs, else direct, else empty: what the path tracer's budgets multiply.
    std::string timeBase() const;
    size_t rowCount() const;
    // The 0-based position of a row in one run's files.
    size_t realTimeRow(size_t scene, const std::string& technique, size_t preset) const;
    size_t pathTracerRow(size_t scene, size_t budget) const;
};

struct BenchUnit {
    size_t scene = 0;
    std::string technique; // a real-time technique, or "pathtracer" when no base runs
    bool withPathTracer = false;
};

// In one run's order.
std::vector<BenchUnit> benchUnits(const BenchMatrix& matrix);

} // namespace lumina::gi
