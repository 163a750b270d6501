#pragma once
// `--technique auto --error-budget E` (docs/measurement.md#choosing-a-technique-automatically):
// a short calibration renders the scene with every candidate technique x preset at a small size
// for a few frames, times each on the GPU (median frame, timestamp queries) and measures its
// relMSE against a low-spp path-traced reference of that size; the cheapest candidate whose
// error is at most E wins. The table is kept on disk, keyed by everything that changes it (the
// scene's contents, the calibration's size, frames, samples and candidates, and the build), so a
// second render of the same scene reuses it.
#include "gi/core/pipeline_cache.h"
#include "gi/scene/scene.h"
#include "rhi/device.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lumina::gi {

struct AutoCandidate {
    std::string technique; // direct, lumen, ddgi or sh-grid
    std::string preset;
    double frameMs = 0.0; // median GPU time per frame over the calibration's frames
    double relMse = 0.0;  // after the last calibration frame
};

struct CalibrationRequest {
    uint32_t width = 64;
    uint32_t height = 64;
    // As many frames as the bench matrix runs (scripts/gpu/bench_matrix.sh): the SH grid settles
    // after 24-48 frames and DDGI's probe history later, so after 8 frames (the first default)
    // only lumen had converged and auto chose it on every scene of the H200 matrix, where the SH
    // grid met the same budget at a tenth of the time (docs/measurement.md).
    uint32_t frames = 128;
    uint32_t referenceSpp = 64;
    std::vector<std::string> techniques{"direct", "lumen", "ddgi", "sh-grid"};
    std::vector<std::string> presets{"low", "medium", "high"};
};

struct Calibration {
    std::vector<AutoCandidate> candidates{}; // techniques x presets, in the request's order
    std::filesystem::path path{};            // the cache file
    bool reused = false;
};

// $LUMINA_CACHE_DIR/calibration and its fallbacks (gi/core/cache_dir.h).
std::filesystem::path defaultCalibrationDirectory();
std::filesystem::path calibrationPath(const std::filesystem::path& directory, const scene::Scene& scene,
                                      const CalibrationRequest& request);

// Reads the cached table or measures it (the reference through the bench's reference cache in
// `referenceDirectory`), reporting each candidate as it is measured.
Calibration loadOrCalibrate(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                            const CalibrationRequest& request, const std::filesystem::path& directory,
                            const std::filesystem::path& referenceDirectory,
                            const std::function<void(const AutoCandidate&)>& measured = {});

// The index of the cheapest candidate (least frameMs) whose relMSE is at most `budget`; none
// when no candidate is that accurate.
std::optional<size_t> cheapestUnder(const std::vector<AutoCandidate>& candidates, double budget);

} // namespace lumina::gi
