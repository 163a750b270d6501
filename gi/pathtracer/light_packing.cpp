#include "gi/pathtracer/light_packing.h"

#include <algorithm>
#include <cmath>

namespace lumina::gi {

namespace {

uint32_t typeCode(scene::LightType type) {
    switch (type) {
    case scene::LightType::Directional:
        return LUMINA_LIGHT_DIRECTIONAL;
    case scene::LightType::Point:
        return LUMINA_LIGHT_POINT;
    case scene::LightType::Spot:
        return LUMINA_LIGHT_SPOT;
    }
    return LUMINA_LIGHT_POINT;
}

} // namespace

gpu::GpuLight packLight(const scene::Light& light) {
    gpu::GpuLight out{};
    const float length = glm::length(light.direction);
    const glm::vec3 direction = length > 0.0f ? light.direction / length : glm::vec3(0.0f, 0.0f, -1.0f);
    out.positionAndType = glm::vec4(light.position, gpu::asfloat(typeCode(light.type)));
    out.directionAndRange = glm::vec4(direction, std::max(light.range, 0.0f));
    out.strength = glm::vec4(light.strength(), 0.0f);
    // KHR_lights_punctual: t = saturate(cos * scale + offset), attenuation = t^2.
    const float cosOuter = std::cos(light.outerConeAngle);
    const float cosInner = std::cos(light.innerConeAngle);
    const float scale = 1.0f / std::max(cosInner - cosOuter, LUMINA_SPOT_MIN_COS_DELTA);
    out.spotScaleOffset = glm::vec4(scale, -cosOuter * scale, 0.0f, 0.0f);
    return out;
}

std::vector<gpu::GpuLight> packLights(const std::vector<scene::Light>& lights) {
    std::vector<gpu::GpuLight> out;
    out.reserve(lights.size());
    for (const scene::Light& light : lights) {
        out.push_back(packLight(light));
    }
    return out;
}

} // namespace lumina::gi
