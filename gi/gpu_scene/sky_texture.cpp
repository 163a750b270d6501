#include "gi/gpu_scene/sky_texture.h"

namespace lumina::gi {

SkyTextureData packUniformSky(const glm::vec3& radiance) {
    return {.width = 1, .height = 1, .texels = {gpu::float4(radiance, 1.0f)}};
}

SkyTextureData packSky(const scene::Scene& scene) {
    if (!scene.skyEnvironment) {
        return packUniformSky(scene.sky);
    }
    const scene::SkyEnvironment& sky = *scene.skyEnvironment;
    SkyTextureData data{.width = sky.width, .height = sky.height, .texels = {}};
    data.texels.reserve(sky.radiance.size());
    for (const glm::vec3& radiance : sky.radiance) {
        data.texels.push_back(gpu::float4(radiance, 1.0f));
    }
    return data;
}

rhi::TextureHandle createSkyTexture(rhi::IDevice& device, const SkyTextureData& data) {
    rhi::TextureHandle texture = device.createTexture({.format = rhi::Format::RGBA32_FLOAT,
                                                       .width = data.width,
                                                       .height = data.height,
                                                       .usage = rhi::TextureUsage::Sampled,
                                                       .debugName = "sky"});
    rhi::writeTexture(device, *texture, {}, data.texels.data());
    return texture;
}

} // namespace lumina::gi
