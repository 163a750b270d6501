#pragma once
// A scene on a test device with everything the screen probes read: the deferred renderer (for
// the GBuffer), the scene's SDFs, a voxel lighting volume the test fills, optionally a surface
// cache, and the gather. Each render() records one frame (SDF compose, deferred frame, surface
// cache update, screen probes), submits it and waits.
#include "gi/core/frame_context.h"
#include "gi/core/pipeline_cache.h"
#include "gi/deferred/buffer_readback.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/gpu_scene/sky_texture.h"
#include "gi/scene/scene.h"
#include "gi/scene/scene_loader.h"
#include "gi/screen_probes/screen_probe_gather.h"
#include "gi/sdf/scene_sdf.h"
#include "gi/sdf/sdf_atlas.h"
#include "gi/surface_cache/surface_cache.h"
#include "rhi/rhi.h"
#include "shaders/screen_probes/screen_probe_shared.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lumina::test {

constexpr uint32_t kSize = 64; // image edge of most screen-probe GPU tests: an 8 x 8 probe grid
constexpr float kPi = 3.14159265358979f;

// cornell_box_point seen from farther back: the box fills the middle, the sky the rest.
inline scene::Scene cornellWithSky() {
    scene::Scene scene = scene::loadScene("cornell_box_point");
    scene.camera.position -= scene.camera.forward * 900.0f;
    return scene;
}

// The slot last frame's copy of the probe in slot p held, the camera and scene unchanged: p for a
// uniform probe; for an adaptive probe the adaptive slot placed at the same pixel; nullopt if there
// was none.
inline std::optional<uint32_t> sameProbeLastFrame(const std::vector<gpu::ScreenProbe>& previous,
                                                  const std::vector<gpu::ScreenProbe>& current, uint32_t p,
                                                  uint32_t uniformProbeCount) {
    if (p < uniformProbeCount) {
        return p;
    }
    for (uint32_t q = uniformProbeCount; q < previous.size(); ++q) {
        if (previous[q].info.x == LUMINA_SP_PROBE_VALID && previous[q].info.y == current[p].info.y &&
            previous[q].info.z == current[p].info.z) {
            return q;
        }
    }
    return std::nullopt;
}

// The Cornell box's surface cache at one 64-texel tile per wall (8.7 mm texels); card padding
// 20 mm, more than the harness's mesh-SDF voxel (555 / 32 = 17 mm) off which open-surface hits
// may lie.
inline surface_cache::SurfaceCacheSettings cornellCacheSettings() {
    surface_cache::SurfaceCacheSettings s;
    s.atlasSize = 512;
    s.texelsPerUnit = 0.1f;
    s.minPaddingUnits = 20.0f;
    return s;
}

// Converges in a dozen updates (0.73^10 < 0.05) instead of the default's 36: enough for tests that
// compare the probes with the cache as it is, not with the path tracer.
inline surface_cache::SurfaceLightingSettings quickCacheLighting() {
    surface_cache::SurfaceLightingSettings s;
    s.schedule.tolerance = 0.05f;
    s.schedule.refinementPasses = 0;
    return s;
}

class ScreenProbeHarness {
public:
    // Voxel lighting is a dims^3 volume over the global SDF's grid: far-field hits land anywhere in
    // it (a cone "hits" where it comes within its radius of a surface, in front of an opening too).
    ScreenProbeHarness(rhi::IDevice& device, rhi::ShaderLibrary& shaders, scene::Scene scene, uint32_t width,
                       uint32_t height, gi::ScreenProbeSettings settings = {}, uint32_t voxelDims = 8,
                       const sdf::SceneSdfSettings& sdfs = sdfSettings())
        : device_(device), scene_(std::move(scene)), pipelines_(device, shaders), gpuScene_(device, scene_),
          renderer_(device, scene_, gpuScene_,
                    {.width = width, .height = height, .log = [](std::string_view) {}}),
          sdf_(device, scene_, sdfs), probes_(device, width, height, settings), camera_(scene_.camera),
          list_(device.createCommandList()), voxelDims_(voxelDims) {
        const gpu::SdfSceneInfo grid = sdf_.sceneInfo();
        voxelMin_ = grid.globalMin;
        voxelMax_ = grid.globalMax;
        voxels_ = device.createTexture({.dimension = rhi::TextureDimension::Texture3D,
                                        .format = rhi::Format::RGBA16_FLOAT,
                                        .width = voxelDims,
                                        .height = voxelDims,
                                        .depth = voxelDims,
                                        .usage = rhi::TextureUsage::Sampled,
                                        .debugName = "test voxel lighting"});
        fillVoxels([](uint32_t, uint32_t, uint32_t) { return glm::vec4(0.0f); });
    }

    static sdf::SceneSdfSettings sdfSettings() {
        sdf::SceneSdfSettings s;
        s.mesh.resolution = 32;
        s.globalResolution = 48;
        s.useCache = false;
        return s;
    }

    // Fills the voxel lighting volume: value(x, y, z) = (premultiplied radiance, occupancy).
    template <typename F>
    void fillVoxels(F value) {
        std::vector<uint16_t> texels;
        for (uint32_t z = 0; z < voxelDims_; ++z) {
            for (uint32_t y = 0; y < voxelDims_; ++y) {
                for (uint32_t x = 0; x < voxelDims_; ++x) {
                    const glm::vec4 v = value(x, y, z);
                    for (int c = 0; c < 4; ++c) {
                        texels.push_back(sdf::floatToHalf(v[c]));
                    }
                }
            }
        }
        rhi::writeTexture(device_, *voxels_, {}, texels.data());
    }

    // A uniform sky for the probes alone, written before each frame (any value, NaN included);
    // without one the probes see the scene's sky (the GpuScene's texture, as the renderer does).
    void setSky(glm::vec3 sky) { sky_ = sky; }
    void setCamera(const scene::Camera& camera) {
        camera_ = camera;
        renderer_.setCamera(camera);
    }
    void useVoxelLighting(bool use) { useVoxels_ = use; }
    // Builds a surface cache of the scene: every render() updates it (lit by the deferred
    // renderer's lights) before the probes run, and hands it to them while `give`.
    void addSurfaceCache(const surface_cache::SurfaceCacheSettings& settings,
                         const surface_cache::SurfaceLightingSettings& lighting = {}) {
        cache_ = std::make_unique<surface_cache::SurfaceCache>(device_, scene_, gpuScene_, sdf_, settings,
                                                               lighting);
    }
    void giveSurfaceCache(bool give) { giveCache_ = give; }
    // Hands the surface cache's voxel lighting to the probes as the caller's own volume (looked up
    // at far hits as a plain volume is) instead of the test's.
    void useCacheVolumeAsPlainVolume(bool use) { cacheVolumeAsPlain_ = use; }

    // Records and runs one frame; returns the names of the timed passes that ran, in order.
    std::vector<std::string> render() {
        list_->begin();
        gi::FrameContext frame(pipelines_, *list_, frameIndex_++);
        sdf_.record(frame);
        renderer_.render(frame);
        std::optional<gi::SurfaceCacheView> cache;
        gi::VoxelLighting voxels{useVoxels_ ? voxels_ : nullptr, voxelMin_, voxelMax_};
        if (cache_) {
            cache_->update(frame, renderer_.shadowedLights());
            if (giveCache_) {
                cache = gi::surfaceCacheView(*cache_);
            }
            if (cacheVolumeAsPlain_) {
                const gpu::VoxelGridInfo& grid = cache_->voxelLighting().grid();
                const glm::vec3 lo = grid.boxMin;
                voxels = {cache_->voxelLighting().volume(), lo, lo + glm::vec3(grid.dims) * grid.voxelSize};
            }
        }
        rhi::TextureHandle sky = gpuScene_.sky;
        if (sky_) {
            const glm::vec4 texel(*sky_, 1.0f);
            list_->writeTexture(*skyOverride_, {}, &texel);
            sky = skyOverride_;
        }
        probes_.record(frame, {.gbuffer = renderer_.gbuffer(),
                               .camera = camera_,
                               .sdf = sdf_,
                               .sky = sky,
                               .voxelLighting = voxels,
                               .surfaceCache = cache});
        list_->end();
        skipped_ = frame.skipped();
        rhi::IQueue& queue = device_.queue(rhi::QueueType::Graphics);
        queue.waitForValue(queue.submit(*list_));
        timings_ = list_->timerResults();
        std::vector<std::string> passes;
        for (const rhi::TimerResult& timer : timings_) {
            passes.push_back(timer.name);
        }
        return passes;
    }

    // Renders until the surface cache has converged: radiosity stopped, and the combine after its
    // last bounce ran in the same frame. Returns the frames rendered (maxFrames: it did not converge).
    uint32_t renderUntilCacheConverged(uint32_t maxFrames) {
        const auto skipped = [&](const char* pass) {
            return std::any_of(skipped_.begin(), skipped_.end(),
                               [&](const gi::SkippedPass& s) { return s.pass == pass; });
        };
        for (uint32_t frame = 1; frame <= maxFrames; ++frame) {
            render();
            if (skipped(surface_cache::RadiosityPass::kTracePassName) &&
                !skipped(surface_cache::SurfaceCacheCombinePass::kPassName)) {
                return frame;
            }
        }
        return maxFrames;
    }

    image::Image read(const rhi::TextureHandle& texture) { return gi::readTextureImage(device_, *texture); }
    template <typename T>
    std::vector<T> read(const rhi::BufferHandle& buffer) {
        return rhi::readBufferAs<T>(device_, *buffer);
    }

    // The passes the last frame skipped, and why.
    const std::vector<gi::SkippedPass>& skipped() const { return skipped_; }
    // GPU time of every pass of the last frame.
    const std::vector<rhi::TimerResult>& timings() const { return timings_; }
    uint32_t voxelDims() const { return voxelDims_; }
    glm::vec3 voxelMin() const { return voxelMin_; }
    glm::vec3 voxelMax() const { return voxelMax_; }
    gi::ScreenProbeGather& probes() { return probes_; }
    gi::DeferredRenderer& renderer() { return renderer_; }
    const scene::Scene& scene() const { return scene_; }
    const sdf::SceneSdf& sdf() const { return sdf_; }
    const rhi::TextureHandle& sceneSky() const { return gpuScene_.sky; }
    const surface_cache::SurfaceCache& cache() const { return *cache_; }

private:
    rhi::IDevice& device_;
    scene::Scene scene_;
    gi::PipelineCache pipelines_;
    gi::GpuScene gpuScene_;
    gi::DeferredRenderer renderer_;
    sdf::SceneSdf sdf_;
    gi::ScreenProbeGather probes_;
    scene::Camera camera_;
    rhi::CommandListHandle list_;
    uint64_t frameIndex_ = 0;
    uint32_t voxelDims_;
    rhi::TextureHandle voxels_;
    glm::vec3 voxelMin_{0.0f}, voxelMax_{0.0f};
    std::optional<glm::vec3> sky_;
    rhi::TextureHandle skyOverride_ = gi::createSkyTexture(device_, gi::packUniformSky(glm::vec3(0.0f)));
    bool useVoxels_ = true;
    std::unique_ptr<surface_cache::SurfaceCache> cache_;
    bool giveCache_ = true;
    bool cacheVolumeAsPlain_ = false;
    std::vector<rhi::TimerResult> timings_;
    std::vector<gi::SkippedPass> skipped_;
};

} // namespace lumina::test
