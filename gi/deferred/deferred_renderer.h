#pragma once
// The real-time frame GI plugs into (docs/deferred.md):
//
//   gbuffer -> sun shadow -> point shadows -> direct light -> composite (+ indirect x albedo)
//
// The renderer owns its targets and records one frame into a FrameContext. Shadow maps are
// re-rendered only when their light or the geometry changes; every pass that does not run
// says why through frame.skip(), which --timings prints.
#include "gi/core/frame_context.h"
#include "gi/deferred/composite_pass.h"
#include "gi/deferred/direct_light_pass.h"
#include "gi/deferred/gbuffer_pass.h"
#include "gi/deferred/light_setup.h"
#include "gi/deferred/point_shadow_pass.h"
#include "gi/deferred/sun_shadow_pass.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::gi {

struct DeferredSettings {
    uint32_t width = 0; // 0: the scene's image size
    uint32_t height = 0;
    uint32_t sunShadowSize = 2048;
    uint32_t pointShadowSize = 512;
    float exposureEv = 0.0f;
    // Receives the renderer's notes (lights left unshadowed); default: std::clog.
    std::function<void(std::string_view)> log;
};

// The lights and shadow maps of the last recorded frame, for passes that light other surfaces
// the way the direct-light pass does (the surface cache's direct light): the same light buffer,
// shadow constants and maps, read through shaders/deferred/shadow_visibility.hlsli.
struct ShadowedLights {
    rhi::BufferHandle shadowConstants; // DeferredShadowConstants
    rhi::BufferHandle lights;          // DeferredLight[lightCount], scene order; at least one element
    uint32_t lightCount = 0;
    rhi::TextureHandle sunShadowMap;    // D32
    rhi::TextureHandle pointShadowMaps; // R32F cube array
    uint64_t lightsVersion = 0;         // changes whenever setLights is called
    // Per light (scene order): the frame its shadow map was last rendered, 0 for a light without
    // one. A change means what the light reaches may have changed (geometry moved in its range).
    std::vector<uint64_t> shadowFrames;
};

class DeferredRenderer {
public:
    // `scene` and `gpuScene` must outlive the renderer.
    DeferredRenderer(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene,
                     DeferredSettings settings = {});

    // Records one frame: every pass, or its skip. The same as recordLighting then recordComposite,
    // between which GI reads the GBuffer and sets the indirect term.
    void render(FrameContext& frame);
    // GBuffer, shadow maps and direct light.
    void recordLighting(FrameContext& frame);
    // HDR = direct + indirect x scale x albedo, tonemapped into the display image.
    void recordComposite(FrameContext& frame);

    void setCamera(const scene::Camera& camera) { camera_ = camera; }
    void setLights(std::vector<scene::Light> lights);
    void setExposure(float ev) { settings_.exposureEv = ev; }
    // Indirect light, times `scale` and albedo in the composite; null: none (the default).
    // Irradiance E from a GI pass takes scale 1/pi (Lambert).
    void setIndirect(rhi::TextureHandle indirect, float scale = 1.0f) {
        indirect_ = std::move(indirect);
        indirectScale_ = scale;
    }
    // Instances moved: `movedRegions` holds their old and new world boxes, `sceneBounds` the
    // scene's bounds now. The next frame re-renders the sun's map and every cube map whose range
    // reaches a region; the others keep theirs.
    void geometryMoved(const scene::Bounds& sceneBounds, std::vector<scene::Bounds> movedRegions);
    // Everything within `bounds` may have moved.
    void geometryChanged(const scene::Bounds& bounds) { geometryMoved(bounds, {bounds}); }

    uint32_t width() const { return settings_.width; }
    uint32_t height() const { return settings_.height; }
    const GBuffer& gbuffer() const { return gbuffer_; }
    const rhi::TextureHandle& direct() const { return direct_; } // RGBA16F linear radiance
    const rhi::TextureHandle& hdr() const { return hdr_; }       // RGBA16F, direct + indirect x albedo
    const rhi::TextureHandle& ldr() const { return ldr_; }       // RGBA8, display-encoded sRGB
    // Null when the scene has no sun / no shadowed point or spot light.
    rhi::TextureHandle sunShadowMap() const;
    rhi::TextureHandle pointShadowMaps() const;
    uint32_t pointShadowCubes() const { return pointShadow_.cubeCount(); }
    const LightSetup& lights() const { return lights_; }
    const std::vector<scene::Light>& sceneLights() const { return sceneLights_; }
    uint64_t lightsVersion() const { return lightsVersion_; }
    // Valid once render() has recorded a frame.
    ShadowedLights shadowedLights() const;

private:
    void uploadConstants(rhi::ICommandList& commands, const std::optional<SunShadowFit>& sun,
                         const std::vector<glm::vec4>& cubes);

    rhi::IDevice& device_;
    const scene::Scene& scene_;
    DeferredSettings settings_;
    scene::Camera camera_;
    std::vector<scene::Light> sceneLights_;
    LightSetup lights_;
    bool lightsDirty_ = true;
    uint64_t lightsVersion_ = 0;
    scene::Bounds bounds_;
    std::vector<scene::Bounds> movedRegions_; // since the last recorded frame
    std::vector<uint64_t> shadowFrames_;      // per light, ShadowedLights::shadowFrames
    rhi::TextureHandle sky_;                  // the GpuScene's
    rhi::TextureHandle indirect_;
    float indirectScale_ = 1.0f;

    GBuffer gbuffer_;
    rhi::TextureHandle direct_;
    rhi::TextureHandle hdr_;
    rhi::TextureHandle ldr_;
    rhi::BufferHandle frameConstants_;
    rhi::BufferHandle shadowConstants_;
    rhi::BufferHandle lightBuffer_;
    uint32_t lightCapacity_ = 0;

    GBufferPass gbufferPass_;
    SunShadowPass sunShadow_;
    PointShadowPass pointShadow_;
    DirectLightPass directLight_;
    CompositePass composite_;
};

} // namespace lumina::gi
