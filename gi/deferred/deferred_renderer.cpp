#include "gi/deferred/deferred_renderer.h"

#include "gi/core/camera.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace lumina::gi {

namespace {

DeferredSettings resolved(DeferredSettings settings, const scene::Scene& scene) {
    if (settings.width == 0 || settings.height == 0) {
        settings.width = scene.image.width;
        settings.height = scene.image.height;
    }
    if (!settings.log) {
        settings.log = [](std::string_view line) { std::clog << "deferred: " << line << '\n'; };
    }
    return settings;
}

rhi::TextureHandle createStorageTarget(rhi::IDevice& device, rhi::Format format, uint32_t width,
                                       uint32_t height, const char* name) {
    return device.createTexture({.format = format,
                                 .width = width,
                                 .height = height,
                                 .usage = rhi::TextureUsage::Storage | rhi::TextureUsage::Sampled,
                                 .debugName = name});
}

rhi::BufferHandle createConstantBuffer(rhi::IDevice& device, uint64_t size, const char* name) {
    return device.createBuffer({.size = size, .usage = rhi::BufferUsage::Constant, .debugName = name});
}

} // namespace

DeferredRenderer::DeferredRenderer(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene,
                                   DeferredSettings settings)
    : device_(device), scene_(scene), settings_(resolved(std::move(settings), scene)), camera_(scene.camera),
      bounds_(scene.worldBounds()), sky_(gpuScene.sky), gbufferPass_(device, scene, gpuScene),
      sunShadow_(device, gpuScene, settings_.sunShadowSize),
      pointShadow_(device, gpuScene, settings_.pointShadowSize), composite_(device) {
    const uint32_t w = settings_.width, h = settings_.height;
    gbuffer_ = GBuffer::create(device, w, h);
    direct_ = createStorageTarget(device, rhi::Format::RGBA16_FLOAT, w, h, "direct light");
    hdr_ = createStorageTarget(device, rhi::Format::RGBA16_FLOAT, w, h, "hdr");
    ldr_ = createStorageTarget(device, rhi::Format::RGBA8_UNORM, w, h, "ldr");
    frameConstants_ =
        createConstantBuffer(device, sizeof(gpu::DeferredFrameConstants), "deferred frame constants");
    shadowConstants_ =
        createConstantBuffer(device, sizeof(gpu::DeferredShadowConstants), "deferred shadow constants");
    setLights(scene.lights);
}

void DeferredRenderer::setLights(std::vector<scene::Light> lights) {
    sceneLights_ = std::move(lights);
    lights_ = setupLights(sceneLights_);
    for (const std::string& line : lights_.unshadowed) {
        settings_.log(line);
    }
    lightsDirty_ = true;
    ++lightsVersion_;
    // Stamps stay with their light: a light that keeps its index and its shadow map keeps its
    // stamp (a changed one gets a new stamp when its map is rendered again), so editing one light
    // does not make the surface cache re-light what the others reach.
    shadowFrames_.resize(sceneLights_.size(), 0);
}

ShadowedLights DeferredRenderer::shadowedLights() const {
    return {.shadowConstants = shadowConstants_,
            .lights = lightBuffer_,
            .lightCount = uint32_t(lights_.lights.size()),
            .sunShadowMap = sunShadow_.map(),
            .pointShadowMaps = pointShadow_.maps(),
            .lightsVersion = lightsVersion_,
            .shadowFrames = shadowFrames_};
}

void DeferredRenderer::geometryMoved(const scene::Bounds& sceneBounds,
                                     std::vector<scene::Bounds> movedRegions) {
    bounds_ = sceneBounds;
    movedRegions_.insert(movedRegions_.end(), movedRegions.begin(), movedRegions.end());
}

rhi::TextureHandle DeferredRenderer::sunShadowMap() const {
    return sunShadow_.valid() ? sunShadow_.map() : nullptr;
}

rhi::TextureHandle DeferredRenderer::pointShadowMaps() const {
    return pointShadow_.cubeCount() > 0 ? pointShadow_.maps() : nullptr;
}

void DeferredRenderer::uploadConstants(rhi::ICommandList& commands, const std::optional<SunShadowFit>& sun,
                                       const std::vector<glm::vec4>& cubes) {
    gpu::DeferredFrameConstants frame{};
    frame.camera = makeGpuCamera(camera_, settings_.width, settings_.height);
    frame.lightCount = uint32_t(lights_.lights.size());
    frame.width = settings_.width;
    frame.height = settings_.height;
    commands.writeBuffer(*frameConstants_, &frame, sizeof(frame));

    gpu::DeferredShadowConstants shadow{};
    if (sun) {
        for (int r = 0; r < 4; ++r) {
            shadow.sunViewProjRows[r] = sun->viewProjRows[r];
        }
        const auto size = float(settings_.sunShadowSize);
        shadow.sunMapSize = size;
        shadow.sunMapInvSize = 1.0f / size;
        shadow.sunTexelWorld = sun->texelWorld;
        shadow.sunDepthRange = sun->depthRange;
    }
    const auto faceSize = float(settings_.pointShadowSize);
    shadow.pointFaceSize = faceSize;
    shadow.pointFaceInvSize = 1.0f / faceSize;
    shadow.pointNearFraction = LUMINA_POINT_SHADOW_NEAR_FRACTION;
    shadow.shadowedPointCount = uint32_t(cubes.size());
    for (size_t i = 0; i < cubes.size(); ++i) {
        shadow.pointLights[i] = {.position = glm::vec3(cubes[i]), .range = cubes[i].w};
    }
    commands.writeBuffer(*shadowConstants_, &shadow, sizeof(shadow));

    if (lightsDirty_) {
        const auto count = std::max<uint32_t>(1, uint32_t(lights_.lights.size()));
        if (count > lightCapacity_) {
            lightBuffer_ = device_.createBuffer({.size = count * sizeof(gpu::DeferredLight),
                                                 .structStride = sizeof(gpu::DeferredLight),
                                                 .usage = rhi::BufferUsage::Structured,
                                                 .debugName = "deferred lights"});
            lightCapacity_ = count;
        }
        std::vector<gpu::DeferredLight> data = lights_.lights;
        data.resize(count); // one zero light when there are none: never read (count 0)
        commands.writeBuffer(*lightBuffer_, data.data(), data.size() * sizeof(gpu::DeferredLight));
        lightsDirty_ = false;
    }
}

void DeferredRenderer::render(FrameContext& frame) {
    recordLighting(frame);
    recordComposite(frame);
}

void DeferredRenderer::recordLighting(FrameContext& frame) {
    std::optional<SunShadowFit> sun;
    if (lights_.sun) {
        sun = fitSunShadow(bounds_, sceneLights_[*lights_.sun].direction, settings_.sunShadowSize);
    }
    std::vector<glm::vec4> cubes;
    for (uint32_t index : lights_.cubeLights) {
        const scene::Light& light = sceneLights_[index];
        cubes.emplace_back(light.position, pointShadowRange(light, bounds_));
    }
    uploadConstants(frame.commands(), sun, cubes);

    gbufferPass_.record(frame, gbuffer_, frameConstants_);
    // The frame a map was rendered stands for its content: the surface cache re-lights the cards
    // a light reaches when it changes.
    const uint64_t frameMark = frame.frameIndex() + 1;
    if (sunShadow_.record(frame, sun, shadowConstants_, !movedRegions_.empty())) {
        shadowFrames_.at(*lights_.sun) = frameMark;
    }
    const std::vector<bool> cubesRendered =
        pointShadow_.record(frame, cubes, shadowConstants_, movedRegions_);
    for (size_t cube = 0; cube < cubesRendered.size(); ++cube) {
        if (cubesRendered[cube]) {
            shadowFrames_.at(lights_.cubeLights[cube]) = frameMark;
        }
    }
    movedRegions_.clear();
    directLight_.record(frame,
                        {.gbuffer = gbuffer_,
                         .frameConstants = frameConstants_,
                         .shadowConstants = shadowConstants_,
                         .lights = lightBuffer_,
                         .sunShadowMap = sunShadow_.map(),
                         .pointShadowMaps = pointShadow_.maps(),
                         .sky = sky_},
                        direct_);
}

void DeferredRenderer::recordComposite(FrameContext& frame) {
    composite_.record(frame,
                      {.direct = direct_,
                       .indirect = indirect_,
                       .indirectScale = indirectScale_,
                       .albedo = gbuffer_.albedo,
                       .exposureEv = settings_.exposureEv},
                      hdr_, ldr_);
}

} // namespace lumina::gi
