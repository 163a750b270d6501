#pragma once
// A FrameRenderer on a test device (docs/gi_tests.md): owns the scene, its upload, the
// pipelines and a command list, renders one frame per submission (waited for) and reads the
// images back; and the path-traced reference the frame is measured against.
//
//   FrameHarness h(device(), shaders(), scene::loadScene("cornell_box"), {.width = 64, .height = 64});
//   h.renderUntilConverged(48);       // the surface cache's radiosity, then 48 frames more
//   measure::relMse(reference, h.hdr());
#include "gi/core/finite_check.h"
#include "gi/core/frame_context.h"
#include "gi/core/pipeline_cache.h"
#include "gi/core/timing_table.h"
#include "gi/deferred/buffer_readback.h"
#include "gi/frame/frame_renderer.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/image/image.h"
#include "gi/pathtracer/path_tracer.h"
#include "gi/scene/scene.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace lumina::test {

struct FrameHarnessSettings {
    uint32_t width = 64;
    uint32_t height = 64;
    gi::GiTechnique technique = gi::GiTechnique::Lumen;
    std::string preset = "low";
    uint32_t probeSpacing = 0; // pixels per screen-probe edge; 0: the preset's
    // Changes to the DDGI preset's settings (the ddgi technique only): fewer probes, a lower
    // hysteresis so that a test converges sooner.
    std::function<void(gi::DdgiSettings&)> adjustDdgi = nullptr;
    // Changes to the lumen preset's settings (the lumen technique only): a smaller atlas.
    std::function<void(gi::LumenSettings&)> adjustLumen = nullptr;
    // Changes to the SH grid preset's settings (the sh-grid technique only).
    std::function<void(gi::ShGridSettings&)> adjustShGrid = nullptr;
    // Runs the finite check (gi/core/finite_check.h) over every pass of every frame;
    // nonFinite() then says what the last frame's first non-finite write was.
    bool checkFinite = false;
};

class FrameHarness {
public:
    FrameHarness(rhi::IDevice& device, rhi::ShaderLibrary& shaders, scene::Scene scene,
                 const FrameHarnessSettings& settings);

    // Renders `count` frames, each submitted and waited for.
    void render(uint32_t count = 1);
    // The same with async compute, as `lumina render --async-compute` submits a frame
    // (FrameRenderer's SplitFrame): raster and async lists, then the gather waiting for the async
    // one. Returns the frames whose async list received passes.
    uint32_t renderWithAsyncCompute(uint32_t count = 1);
    // Renders until the surface cache's radiosity has converged, then `extraFrames` more (the
    // screen probes' temporal filters settle); at most `maxFrames` in all. Returns the frames
    // rendered; converged() says whether the cache got there.
    uint32_t renderUntilConverged(uint32_t extraFrames, uint32_t maxFrames = 2000);
    bool converged() const;

    // R, G, B of the last frame: the final HDR radiance, the deferred direct light (emission,
    // lights, sky on the background: what the direct technique shows), and what GI added
    // (final less direct).
    image::Image hdr();
    image::Image direct();
    image::Image indirect();
    image::Image read(const rhi::TextureHandle& texture) { return gi::readTextureImage(device_, *texture); }

    gi::FrameRenderer& renderer() { return renderer_; }
    const gi::LumenGi& lumen() const { return *renderer_.lumen(); }    // the lumen technique only
    const gi::DdgiGi& ddgi() const { return *renderer_.ddgi(); }       // the ddgi technique only
    const gi::ShGridGi& shGrid() const { return *renderer_.shGrid(); } // the sh-grid technique only
    const scene::Scene& scene() const { return scene_; }
    gi::PipelineCache& pipelines() { return pipelines_; }
    uint32_t frames() const { return frames_; }
    const gi::TimingTable& timings() const { return timings_; }
    // The GPU scene the renderer draws (tests that poison it behind the renderer's back).
    gi::GpuScene& gpuScene() { return gpuScene_; }
    // With checkFinite: the finite check, and the first non-finite write of the last frame.
    gi::FiniteCheck* finiteCheck() { return finiteCheck_.get(); }
    const std::optional<gi::NonFiniteWrite>& nonFinite() const { return nonFinite_; }

private:
    rhi::IDevice& device_;
    scene::Scene scene_;
    gi::GpuScene gpuScene_;
    gi::PipelineCache pipelines_;
    gi::FrameRenderer renderer_;
    rhi::CommandListHandle list_;
    rhi::CommandListHandle asyncList_;  // created by the first renderWithAsyncCompute
    rhi::CommandListHandle gatherList_; // likewise
    gi::TimingTable timings_;
    uint32_t frames_ = 0;
    std::unique_ptr<gi::FiniteCheck> finiteCheck_;
    std::optional<gi::NonFiniteWrite> nonFinite_;
};

// The lumen preset `name` for `scene` as the tests run it: the mesh SDFs built here, not read
// from the user's cache.
gi::LumenSettings testLumenSettings(const std::string& name, const scene::Scene& scene);
// The DDGI preset likewise.
gi::DdgiSettings testDdgiSettings(const std::string& name, const scene::Scene& scene);

// R, G, B of an image (drops A and any other channel).
image::Image rgbOnly(const image::Image& image);
// R, G, B of `prefix`.R/G/B ("direct", "indirect": the path tracer's AOVs).
image::Image rgbOf(const image::Image& image, const std::string& prefix);

// The path tracer's image of `scene` at pixel centres (jitter off, as the raster samples them),
// with AOVs, after `spp` samples per pixel.
gi::PathTracerResult pathTracedReference(rhi::IDevice& device, gi::PipelineCache& pipelines,
                                         const scene::Scene& scene, uint32_t width, uint32_t height,
                                         uint32_t spp);

} // namespace lumina::test
