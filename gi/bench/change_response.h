#pragma once
// How a real-time technique follows a change in an animated scene (docs/dynamic_scenes.md,
// "Figures"): the scene plays its animation for `changeFrames` frames and then holds still at
// that pose; the figures say how far its image lags behind a fresh renderer of the held pose
// (built from scratch at that pose and run until converged), how many frames and GPU
// milliseconds it takes to come within `tolerance` relMSE of it, and what a frame costs while
// things move against a static frame.
#include "gi/core/pipeline_cache.h"
#include "gi/frame/gi_technique.h"
#include "gi/scene/scene.h"
#include "rhi/device.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lumina::gi {

struct ChangeResponseRequest {
    uint32_t width = 128;
    uint32_t height = 128;
    uint32_t changeFrames = 120;       // frames the animation plays (frames 0 .. changeFrames - 1)
    uint32_t maxRecoveryFrames = 300;  // frames after that before giving up
    uint32_t maxReferenceFrames = 600; // the fresh renderer's limit to converge
    double tolerance = 0.01;           // relMSE against the fresh render that counts as recovered
};

struct ChangeResponse {
    std::string scene;
    std::string technique;
    std::string preset;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t changeFrames = 0;
    double movingFrameMs = 0.0; // median GPU time of the frames that applied a change
    double staticFrameMs = 0.0; // median GPU time of the fresh renderer's frames once it settled
    double relMseAtStop = 0.0;  // the last animated frame against the fresh render (the lag)
    // The same over the pixels the change touched only: where converged renders of the first pose
    // and of the held pose differ by more than a tenth. Old light left behind (a ghost of the block
    // where it was, a shadow that has not moved on) is concentrated there.
    double changedRegionRelMseAtStop = 0.0;
    double changedRegionFraction = 0.0;      // of the image's pixels
    std::vector<double> relMseAfter;         // after 1, 2, 4, 8, ... frames held still (up to recovery)
    std::optional<uint32_t> framesToRecover; // frames held still until within tolerance; none: not
    double msToRecover = 0.0;                // GPU time of those frames
    uint32_t referenceFrames = 0;            // frames the fresh renderer ran
};

// Throws std::invalid_argument for a scene without animation, a zero size or changeFrames, or an
// unknown preset.
ChangeResponse measureChangeResponse(rhi::IDevice& device, PipelineCache& pipelines,
                                     const scene::Scene& scene, GiTechnique technique,
                                     const std::string& preset, const ChangeResponseRequest& request);

void writeChangeResponseCsv(const std::filesystem::path& path, const std::vector<ChangeResponse>& rows);

} // namespace lumina::gi
