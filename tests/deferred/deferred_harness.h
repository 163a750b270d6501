#pragma once
// A deferred renderer on a test device: owns the scene, its upload and a command list, and
// renders one frame at a time (submitted and waited for), returning what ran and what skipped.
#include "gi/core/frame_context.h"
#include "gi/core/pipeline_cache.h"
#include "gi/deferred/buffer_readback.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"

#include <algorithm>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace lumina::test {

inline gpu::float3 rgbAt(const image::Image& image, uint32_t x, uint32_t y) {
    const image::Rgb c = image.rgbAt(x, y);
    return {c.r, c.g, c.b};
}

// The GBuffer targets as read back.
struct GBufferImages {
    image::Image albedo, normal, material, position, depth;
};

// What the direct-light pass computes where nothing is in the way, from the GBuffer as read
// back and the shared light model: emission, and albedo / pi x irradiance of every light.
struct Unshadowed {
    gpu::float3 emission;
    gpu::float3 reflected;
};

inline Unshadowed unshadowed(const gi::LightSetup& lights, const GBufferImages& gbuffer, uint32_t x,
                             uint32_t y) {
    const gpu::float3 n = rgbAt(gbuffer.normal, x, y);
    const gpu::float3 p = rgbAt(gbuffer.position, x, y);
    gpu::float3 irradiance(0.0f);
    for (const gpu::DeferredLight& light : lights.lights) {
        const gpu::LightSample sample = gpu::evaluateLight(light.light, p);
        irradiance += sample.irradiance * std::max(0.0f, glm::dot(n, sample.direction));
    }
    return {rgbAt(gbuffer.material, x, y),
            rgbAt(gbuffer.albedo, x, y) * irradiance * std::numbers::inv_pi_v<float>};
}

class DeferredHarness {
public:
    // The GpuScene is made here unless one is given (e.g. the path tracer's).
    DeferredHarness(rhi::IDevice& device, rhi::ShaderLibrary& shaders, scene::Scene scene, uint32_t width,
                    uint32_t height, const gi::GpuScene* gpuScene = nullptr, uint32_t sunShadowSize = 2048)
        : device_(device), scene_(std::move(scene)), pipelines_(device, shaders),
          ownScene_(gpuScene ? nullptr : std::make_unique<gi::GpuScene>(device, scene_)),
          renderer_(device, scene_, gpuScene ? *gpuScene : *ownScene_,
                    {.width = width,
                     .height = height,
                     .sunShadowSize = sunShadowSize,
                     .log = [this](std::string_view line) { log_.emplace_back(line); }}),
          list_(device.createCommandList()) {}

    struct Frame {
        std::vector<std::string> passes; // timed passes that ran, in order (repeats removed)
        std::vector<gi::SkippedPass> skipped;
        bool ran(std::string_view pass) const {
            return std::find(passes.begin(), passes.end(), pass) != passes.end();
        }
        std::string skipReason(std::string_view pass) const {
            for (const gi::SkippedPass& skip : skipped) {
                if (skip.pass == pass) {
                    return skip.reason;
                }
            }
            return {};
        }
    };

    Frame render() {
        list_->begin();
        gi::FrameContext frame(pipelines_, *list_, frameIndex_++);
        renderer_.render(frame);
        list_->end();
        rhi::IQueue& queue = device_.queue(rhi::QueueType::Graphics);
        queue.waitForValue(queue.submit(*list_));
        Frame out;
        for (const rhi::TimerResult& timer : list_->timerResults()) {
            if (out.passes.empty() || out.passes.back() != timer.name) {
                out.passes.push_back(timer.name);
            }
        }
        out.skipped = frame.skipped();
        return out;
    }

    image::Image read(const rhi::TextureHandle& texture) { return gi::readTextureImage(device_, *texture); }
    GBufferImages readGBuffer() {
        const gi::GBuffer& g = renderer_.gbuffer();
        return {read(g.albedo), read(g.normal), read(g.material), read(g.position), read(g.depth)};
    }

    gi::DeferredRenderer& renderer() { return renderer_; }
    const scene::Scene& scene() const { return scene_; }
    const std::vector<std::string>& log() const { return log_; }

private:
    rhi::IDevice& device_;
    scene::Scene scene_;
    gi::PipelineCache pipelines_;
    std::unique_ptr<gi::GpuScene> ownScene_;
    std::vector<std::string> log_;
    gi::DeferredRenderer renderer_;
    rhi::CommandListHandle list_;
    uint64_t frameIndex_ = 0;
};

} // namespace lumina::test
