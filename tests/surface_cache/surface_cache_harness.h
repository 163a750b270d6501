#pragma once
// A scene's surface cache on the test device with everything it needs (GPU scene, SDFs), and
// updates run one submission each, with their timers and skips kept: the shared setup of the
// surface-cache lighting tests.
#include "gi/core/pipeline_cache.h"
#include "gi/core/timing_table.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"
#include "gi/sdf/scene_sdf.h"
#include "gi/surface_cache/surface_cache.h"

#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lumina::test {

inline sdf::SceneSdfSettings smallSdfSettings() {
    sdf::SceneSdfSettings s;
    s.mesh.resolution = 64;
    s.globalResolution = 64;
    s.useCache = false;
    return s;
}

class SurfaceCacheHarness {
public:
    SurfaceCacheHarness(rhi::IDevice& device, rhi::ShaderLibrary& shaders, scene::Scene sceneIn,
                        const surface_cache::SurfaceCacheSettings& settings,
                        const surface_cache::SurfaceLightingSettings& lighting = {})
        : device_(device), scene(std::move(sceneIn)), gpuScene(device, scene),
          sdf(device, scene, smallSdfSettings()), pipelines(device, shaders),
          cache(device, scene, gpuScene, sdf, settings, lighting) {}

    // Records one frame (SDF compose, the lights' frame when given: it records its passes and
    // returns its lights, then one cache update), submits it and waits; returns the passes it
    // skipped and adds its timers to `timings`.
    using LightsFrame = std::function<std::optional<gi::ShadowedLights>(gi::FrameContext&)>;
    // With a `viewer`, the cards' levels of detail follow it (SurfaceCache::update).
    std::vector<gi::SkippedPass> update(const LightsFrame& lights = {},
                                        const std::optional<glm::vec3>& viewer = std::nullopt) {
        rhi::CommandListHandle list = device_.createCommandList();
        list->begin();
        gi::FrameContext frame(pipelines, *list, frameIndex_++);
        sdf.record(frame);
        cache.update(frame, lights ? lights(frame) : std::nullopt, viewer);
        list->end();
        rhi::IQueue& queue = device_.queue(list->queueType());
        queue.waitForValue(queue.submit(*list));
        timings.addFrame(list->timerResults(), frame.skipped());
        return frame.skipped();
    }

    rhi::IDevice& device_;
    scene::Scene scene;
    gi::GpuScene gpuScene;
    sdf::SceneSdf sdf;
    gi::PipelineCache pipelines;
    surface_cache::SurfaceCache cache;
    gi::TimingTable timings{1};

private:
    uint64_t frameIndex_ = 0;
};

// The card that owns atlas texel (x, y), or kNoOwner.
inline uint32_t atlasTexelOwner(const surface_cache::SurfaceCache& cache, uint32_t x, uint32_t y) {
    const surface_cache::TileAllocator& atlas = cache.cards().atlas();
    return atlas.ownerTable()[(y / surface_cache::kTileSize) * atlas.tilesX() + x / surface_cache::kTileSize];
}

// World positions of every atlas texel's captured surface (its centre), from the capture depth
// and the owning card's map; (0,0,0) where no card owns the texel.
inline std::vector<glm::vec3> atlasWorldPositions(rhi::IDevice& device,
                                                  const surface_cache::SurfaceCache& cache) {
    const uint32_t size = cache.atlas().size();
    const std::vector<uint8_t> bytes = rhi::readTexture(device, *cache.capture().depth());
    std::vector<float> depth(size_t(size) * size);
    std::memcpy(depth.data(), bytes.data(), depth.size() * sizeof(float));
    std::vector<glm::vec3> world(depth.size(), glm::vec3(0.0f));
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            const uint32_t card = atlasTexelOwner(cache, x, y);
            if (card == surface_cache::kNoOwner) {
                continue;
            }
            const gpu::SurfaceCard& c = cache.cards().cards()[card];
            const glm::mat4 toCard = glm::transpose(
                glm::mat4(c.worldToCard0, c.worldToCard1, c.worldToCard2, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)));
            const glm::vec2 uv = (glm::vec2(x, y) + 0.5f - glm::vec2(c.atlasRect.x, c.atlasRect.y)) /
                                 glm::vec2(c.atlasRect.z, c.atlasRect.w);
            const size_t i = size_t(y) * size + x;
            world[i] = glm::vec3(glm::inverse(toCard) * glm::vec4(uv, depth[i], 1.0f));
        }
    }
    return world;
}

// The reason a pass was skipped, or "" when it ran.
inline std::string skipReason(const std::vector<gi::SkippedPass>& skipped, const std::string& pass) {
    for (const gi::SkippedPass& s : skipped) {
        if (s.pass == pass) {
            return s.reason;
        }
    }
    return "";
}

} // namespace lumina::test
