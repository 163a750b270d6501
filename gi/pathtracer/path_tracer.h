#pragma once
// The reference path tracer: progressive accumulation of one sample per pixel per pass, over
// tiles small enough that no dispatch runs long. Each pixel keeps the running mean of its
// radiance and the sum of squared deviations (Welford), so the result carries a per-pixel
// variance; optional AOVs (albedo, normal, direct, indirect) accumulate alongside.
//
//   PathTracerScene traced(device, scene);
//   PathTracer tracer(device, traced, scene, {.width = 64, .height = 64});
//   FrameContext frame(pipelines, *list, 0);
//   tracer.recordSamples(frame, 16);   // submit the list and wait, then:
//   PathTracerResult result = tracer.readResult();
//
// Conventions (camera, pixel footprint, units, lights, random numbers): docs/conventions.md.
#include "gi/core/frame_context.h"
#include "gi/image/image.h"
#include "gi/pathtracer/path_tracer_scene.h"
#include "gi/scene/scene.h"
#include "shaders/pathtracer/pathtracer_shared.h"

#include <cstdint>
#include <span>
#include <vector>

namespace lumina::gi {

struct PathTracerSettings {
    uint32_t width = 0; // 0: the scene's image size
    uint32_t height = 0;
    // Scattering events per path: 0 shows emission and sky only, 1 direct light only. Russian
    // roulette ends paths long before the default in anything but a furnace (where the bias
    // of stopping after N bounces is rho^(N+1) of the answer).
    uint32_t maxBounces = 1024;
    uint32_t rouletteStartBounce = 3; // Russian roulette from this many bounces on
    uint32_t seed = 1;
    bool jitter = true; // sample the whole pixel footprint; false: the pixel centre only
    bool aovs = false;
    // Rows [firstRow, firstRow + rowCount) only (rowCount 0: every row), for a shard of a
    // reference (`lumina reference --shard`). A pixel's random numbers depend on its place in
    // the whole image, never on the rows traced, so the shards of an image stitch into exactly
    // the image one run makes; the result holds these rows only.
    uint32_t firstRow = 0;
    uint32_t rowCount = 0;
    uint32_t maxPixelsPerDispatch = 1u << 18; // tiles of at most this many pixels (512 x 512)
};

// Channel names of the result image: R, G, B (linear radiance, the mean over the samples),
// variance.R/G/B (the variance of that mean: sample variance / samples), and with AOVs
// albedo.R/G/B, normal.X/Y/Z, direct.R/G/B, indirect.R/G/B.
struct PathTracerResult {
    image::Image image;
    uint32_t samples = 0;
    uint64_t rays = 0;                      // every ray traced so far, shadow rays included
    uint64_t nonFiniteSamples = 0;          // NaN/Inf samples replaced by 0
    double meanRelativeStandardError = 0.0; // see relativeStandardError
};

class PathTracer {
public:
    // `traced` must outlive the tracer; the camera, sky and (unless settings say) image size
    // come from `scene`.
    PathTracer(rhi::IDevice& device, const PathTracerScene& traced, const scene::Scene& scene,
               const PathTracerSettings& settings);

    // Records `count` more samples per pixel (one pass per sample and tile); the results
    // are there once the command list has run.
    void recordSamples(FrameContext& frame, uint32_t count);
    // Starts again from sample 0 (the buffers are overwritten by the next sample).
    void restart() { samples_ = 0; }
    uint32_t samples() const { return samples_; }
    uint64_t pixelCount() const { return uint64_t(settings_.width) * settings_.height; }
    // The rows traced: settings().firstRow onwards, this many.
    uint32_t rowCount() const { return settings_.rowCount; }
    const PathTracerSettings& settings() const { return settings_; }

    // Reads the accumulation back (blocking; the recorded work must have been submitted).
    PathTracerResult readResult() const;
    // Just the convergence figure (reads back two buffers).
    double meanRelativeStandardError() const;

private:
    // The traced rows of a whole-image buffer read back.
    template <typename T>
    std::span<const T> tracedRows(const std::vector<T>& pixels) const;

    rhi::IDevice& device_;
    const PathTracerScene& traced_;
    PathTracerSettings settings_;
    uint32_t samples_ = 0;
    rhi::BufferHandle constants_;
    rhi::BufferHandle mean_;
    rhi::BufferHandle m2_;
    rhi::BufferHandle counts_;
    rhi::BufferHandle aovs_;
};

// The per-pixel relative standard error of the luminance estimate, regularised as the
// measurement's relMSE is (docs/measurement.md): sqrt(m2 / (n (n - 1))) / sqrt(mean^2 + 0.01),
// averaged over the pixels. m2 and mean are the luminance lanes (w) of the accumulation.
double relativeStandardError(std::span<const gpu::float4> mean, std::span<const gpu::float4> m2,
                             uint32_t samples);

} // namespace lumina::gi
