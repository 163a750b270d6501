#pragma once
// One bench configuration run for real: a technique at a quality preset renders a scene for
// a number of frames; its images at checkpoint frames (1, 2, 4, ... and the last) are
// measured against the path-traced reference, and its passes are timed by GPU timestamps.
//
// Techniques:
//   direct      the deferred renderer (GBuffer, shadows, direct light, composite), no GI;
//               presets low, medium, high set the shadow-map resolutions.
//   lumen       the same deferred renderer plus the lumen GI (SDFs, surface cache, screen
//               probes) through FrameRenderer; presets are lumenPreset's (gi/frame/gi_technique.h)
//   ddgi        the DDGI probe volumes on the same SDFs and surface cache (gi/ddgi/, ddgiPreset)
//               with the direct preset's shadow maps of the same name.
//   sh-grid     the SH probe grid baked from raster cube maps (gi/sh_grid/, shGridPreset), the
//               same shadow maps.
//   pathtracer  the reference path tracer with a fixed number of samples per pixel per frame,
//               accumulating across frames (so "converged" is many frames' samples).
//
// One definition of the indirect term for every technique: the radiance that indirect light
// adds at the primary hit. For the real-time techniques that is what the composite adds,
// indirectScale x E x albedo (E the GI's irradiance, albedo the GBuffer's; black for direct);
// for the path tracer, its paths of two or more bounces (the `indirect` AOV), which is what the
// reference's `indirect` AOV holds too.
#include "gi/bench/reference_cache.h"
#include "gi/core/pipeline_cache.h"
#include "gi/core/timing_table.h"
#include "gi/frame/gi_technique.h"
#include "gi/image/image.h"
#include "gi/scene/scene.h"
#include "rhi/device.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lumina::gi {

struct Checkpoint {
    uint32_t frame = 0;        // 1-based: the error after this many frames
    double relMse = 0.0;       // final image against the reference radiance
    double indirectRelMse = 0; // indirect term against the reference's indirect AOV
    double flip = 0.0;         // mean LDR-FLIP of the final image
};

struct TechniqueRun {
    std::string technique;
    std::string preset;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t frames = 0;
    uint32_t samplesPerFrame = 0; // path tracer only
    double frameMs = 0.0;         // median GPU time of a frame
    std::vector<double> frameMsEach{}; // every frame's GPU time, in order
    std::vector<PassTiming> passes{};
    // The frame after which the technique's per-frame work stopped changing: lumen's surface
    // cache converged (radiosity stops), 1 for direct (frame 1 draws the shadow maps) and the
    // path tracer; none when lumen's surface cache did not converge within the run.
    std::optional<uint32_t> settledAfterFrame{};
    // Median GPU time of the frames after settledAfterFrame (what a frame costs once converged)
    // and the passes over those frames; none when no frame came after it.
    std::optional<double> settledFrameMs{};
    std::vector<PassTiming> settledPasses{};
    std::vector<Checkpoint> checkpoints{}; // ascending frames; the last is "converged"
    uint32_t framesToConverge = 0;         // first checkpoint within 5% of the last one's relMSE
    uint64_t gpuMemoryBytes = 0;           // device memory the technique (with its scene upload) holds
    uint64_t nonFinitePixels = 0;          // in any checkpoint's final or indirect image; must be 0
    image::Image finalImage{};             // R, G, B after the last frame
    std::vector<SkipCount> skips{};        // every pass skipped in some frame, why, and how often
};

struct RunRequest {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t frames = 16;
    uint32_t samplesPerFrame = 1; // path tracer only
    uint32_t seed = 1;
    // Passes whose skips of unchanged work are forced off in every frame (FrameContext::mayReuse).
    std::vector<std::string> forcedPasses{};
};

// A real-time technique (direct, lumen or ddgi) through FrameRenderer. Throws std::invalid_argument
// for an unknown preset (preset.h) and what the technique throws.
TechniqueRun runRealTime(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                         GiTechnique technique, const std::string& preset, const RunRequest& request,
                         const Reference& reference);

TechniqueRun runPathTracer(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                           const std::string& preset, const RunRequest& request, const Reference& reference);

// GPU milliseconds the path tracer takes for one sample per pixel at this size (the median of
// a few samples after one that warms the kernel up): what equal time is computed from.
double pathTracerMsPerSample(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                             uint32_t width, uint32_t height);

// 1, 2, 4, ... up to and including `frames`.
std::vector<uint32_t> checkpointFrames(uint32_t frames);
// The first checkpoint whose relMSE is within `tolerance` (relative) of the last one's.
uint32_t framesToConverge(const std::vector<Checkpoint>& checkpoints, double tolerance = 0.05);

} // namespace lumina::gi
