#pragma once
// The sky on the GPU: one RGBA32F latitude-longitude texture that every ray leaving the scene
// reads through shaders/common/sky_sampling.hlsli (the deferred background, the path tracer's
// misses, screen-probe and surface-cache radiosity misses). A uniform sky is a 1x1 texture,
// so one lookup serves both kinds and a uniform sky reads back exactly its radiance.
#include "gi/scene/scene.h"
#include "rhi/rhi.h"
#include "shaders/common/shared_types.h"

#include <cstdint>
#include <vector>

namespace lumina::gi {

// Texels rows top (the zenith) to bottom, rgb radiance (intensity applied), a = 1.
struct SkyTextureData {
    uint32_t width = 1;
    uint32_t height = 1;
    std::vector<gpu::float4> texels;
};

// The scene's environment, else its uniform sky as one texel.
SkyTextureData packSky(const scene::Scene& scene);
SkyTextureData packUniformSky(const glm::vec3& radiance);

// A sampled RGBA32F texture holding `data` (uploaded before it returns).
rhi::TextureHandle createSkyTexture(rhi::IDevice& device, const SkyTextureData& data);

} // namespace lumina::gi
