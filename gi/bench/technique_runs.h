#pragma once
// One bench configuration run for real: a technique at a quality preset renders a scene for
// a number of frames; its images at checkpoint frames (1, 2, 4, ... and the last) are
// measured against the path-traced reference, and its passes are timed by GPU timestamps.
//
// Techniques so far:
//   direct      the deferred renderer (GBuffer, shadows, direct light, composite), no GI;
//               presets low, medium, high set the shadow-map resolutions.
//   pathtracer  the reference path tracer with a fixed number of samples per pixel per frame,
//               accumulating across frames (so "converged" is many frames' samples).
#include "gi/bench/reference_cache.h"
#include "gi/core/pipeline_cache.h"
#include "gi/core/timing_table.h"
#include "gi/image/image.h"
#include "gi/scene/scene.h"
#include "rhi/device.h"

#include <cstdint>
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
    std::vector<PassTiming> passes{};
    std::vector<Checkpoint> checkpoints{}; // ascending frames; the last is "converged"
    uint32_t framesToConverge = 0;         // first checkpoint within 5% of the last one's relMSE
    uint64_t gpuMemoryBytes = 0;           // device memory the technique (with its scene upload) holds
    uint64_t nonFinitePixels = 0;          // in any checkpoint image; must be 0
    image::Image finalImage{};             // R, G, B after the last frame
};

struct RunRequest {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t frames = 16;
    uint32_t samplesPerFrame = 1; // path tracer only
    uint32_t seed = 1;
};

// The shadow-map sizes of a direct-renderer preset; std::invalid_argument naming the presets
// for an unknown name.
struct DirectPreset {
    uint32_t sunShadowSize = 2048;
    uint32_t pointShadowSize = 512;
};
DirectPreset directPreset(const std::string& name);
const std::vector<std::string>& directPresetNames();

TechniqueRun runDirect(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                       const std::string& preset, const RunRequest& request, const Reference& reference);

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
