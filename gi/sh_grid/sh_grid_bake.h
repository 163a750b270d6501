#pragma once
// The bake of a set of probes (docs/sh_grid.md, "Baking"): for each probe, six cube faces of
// the scene rendered at its position through the deferred renderer's own passes (the raster
// GBuffer, then the direct-light kernel with the frame's shadow maps and the sky), each face
// projected onto SH9 on the GPU, then the six combined and convolved with the clamped cosine.
//
//   per probe: 6 x (sh grid: bake gbuffer -> sh grid: bake direct light -> sh grid: project)
//              -> sh grid: combine
#include "gi/core/frame_context.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/deferred/direct_light_pass.h"
#include "gi/deferred/gbuffer_pass.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/sh_grid/sh_grid_combine_pass.h"
#include "gi/sh_grid/sh_grid_project_face_pass.h"
#include "gi/sh_grid/sh_grid_resources.h"
#include "gi/sh_grid/sh_grid_settings.h"

#include <span>
#include <vector>

namespace lumina::gi {

// The camera of cube face `face` (0..5: +x, -x, +y, -y, +z, -z) at `position`: 90 degrees,
// square.
scene::Camera shGridFaceCamera(const glm::vec3& position, uint32_t face, float nearPlane, float farPlane);
// The projection's constants for a face rendered with `camera` (its right and up as the
// rasteriser used them).
gpu::ShGridFaceConstants shGridFaceConstants(const gpu::GpuCamera& camera, uint32_t face, uint32_t faceSize,
                                             bool bounce);

class ShGridBake {
public:
    // `scene` and `gpuScene` must outlive it.
    ShGridBake(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene,
               const ShGridSettings& settings);

    static constexpr const char* kGBufferName = "sh grid: bake gbuffer";
    static constexpr const char* kDirectName = "sh grid: bake direct light";

    // After deferred.recordLighting(frame): its lights and shadow maps light the faces.
    void record(FrameContext& frame, const DeferredRenderer& deferred, const ShGridResources& r,
                std::span<const uint32_t> probes);

    // The radiance of the last face baked (its -z face of the last probe): a debug view.
    const rhi::TextureHandle& lastFaceRadiance() const { return radiance_; }

private:
    uint32_t faceSize_;
    bool bounce_;
    float nearPlane_, farPlane_;
    rhi::TextureHandle sky_;
    GBufferPass gbufferPass_;
    DirectLightPass directLight_;
    ShGridProjectFacePass project_;
    ShGridCombinePass combine_;
    GBuffer face_;                               // one face's GBuffer, reused face after face
    rhi::TextureHandle radiance_;                // one face's radiance
    std::vector<rhi::BufferHandle> faceCameras_; // DeferredFrameConstants per (probe slot, face)
};

} // namespace lumina::gi
