#pragma once
// The interface every GI technique implements (docs/gi.md, "Techniques"): what FrameRenderer,
// `lumina bench` and the viewer need of lumen, DDGI or any later technique, so that adding one
// touches no other technique's code. A technique records its passes between the deferred
// renderer's lighting and its composite, and hands the composite an irradiance texture:
//
//   deferred.recordLighting(frame);
//   technique.record(frame, deferred, camera);
//   deferred.setIndirect(technique.indirect(), technique.indirectScale());
//   deferred.recordComposite(frame);
//
// makeGiTechniqueRenderer (gi_technique_factory.h) builds the one a FrameRenderer asks for.
#include "gi/core/frame_context.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/frame/gi_technique.h"
#include "gi/scene/scene.h"

#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <vector>

namespace lumina::gi {

// GPU memory one part of a technique allocated when it was built (device allocation deltas).
struct GiMemoryPart {
    std::string name; // "SDFs", "surface cache", "screen probes", "DDGI probe volumes", ...
    uint64_t bytes = 0;
};

// A texture a technique exposes to the debug views (the viewer's menu, --dump-buffers): its
// atlases, its per-pixel results.
struct GiDebugTexture {
    std::string name; // as the menu lists it: "ddgi: irradiance atlas"
    rhi::TextureHandle texture;
    float displayScale = 1.0f; // multiplies the texels before tone mapping for display
};

class GiTechniqueRenderer {
public:
    virtual ~GiTechniqueRenderer() = default;

    virtual GiTechnique technique() const = 0;
    // After deferred.recordLighting(frame) of the frame `camera` shows.
    virtual void record(FrameContext& frame, const DeferredRenderer& deferred,
                        const scene::Camera& camera) = 0;
    // Async compute (docs/performance.md, change 3): records into `async`, a compute-queue list
    // the GPU runs beside this frame's raster, those of this frame's passes that read nothing the
    // raster writes, and returns true; the next record() then records only the rest. Returns
    // false and records nothing when this frame's passes need the graphics queue (a raster pass)
    // or the raster's output: then record() records them all. The caller makes record()'s work
    // wait for `async`'s on the GPU. Called after deferred.recordLighting(), before record().
    virtual bool recordBesideRaster(FrameContext& async, const DeferredRenderer& deferred,
                                    const scene::Camera& camera) {
        (void)async, (void)deferred, (void)camera;
        return false;
    }
    // The next frame keeps no view-dependent temporal history (a camera cut).
    virtual void resetHistory() = 0;
    // True once what the technique accumulates over frames has settled for a static scene (the
    // tests and the bench measure after it).
    virtual bool converged() const = 0;

    // A dynamic scene's changes, recorded at the next record() (FrameRenderer applies them).
    // An instance moved from `before` to `after` (world boxes).
    virtual void moveInstance(uint32_t instance, const glm::mat4& transform, const scene::Bounds& before,
                              const scene::Bounds& after, std::span<const scene::Light> lights) = 0;
    // The lights changed (DeferredRenderer::setLights made `lightsVersion`); `reach` holds the
    // world boxes the changed lights reached before or reach now.
    virtual void setLights(std::span<const scene::Light> lights, uint64_t lightsVersion,
                           std::span<const scene::Bounds> reach) = 0;
    // A material the instance draws changed (emission); `reach` is where its light may land.
    virtual void instanceMaterialChanged(uint32_t instance, const scene::Bounds& reach) = 0;

    // Irradiance E per pixel (RGBA16F or RGBA32F; 0 on sky), what the composite multiplies by
    // indirectScale() x albedo.
    virtual rhi::TextureHandle indirect() const = 0;
    // A Lambertian surface of albedo a sends a x E / pi.
    virtual float indirectScale() const { return float(std::numbers::inv_pi); }

    virtual std::vector<GiMemoryPart> memory() const = 0;
    virtual std::vector<GiDebugTexture> debugTextures() const = 0;
};

} // namespace lumina::gi
