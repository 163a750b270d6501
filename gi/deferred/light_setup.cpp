#include "gi/deferred/light_setup.h"

#include "gi/pathtracer/light_packing.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lumina::gi {

namespace {

std::string lightName(const scene::Light& light, size_t index) {
    return std::string(scene::lightTypeName(light.type)) + " light " + std::to_string(index) +
           (light.name.empty() ? "" : " '" + light.name + "'");
}

} // namespace

LightSetup setupLights(std::span<const scene::Light> lights) {
    LightSetup setup;
    for (size_t i = 0; i < lights.size(); ++i) {
        const scene::Light& light = lights[i];
        gpu::DeferredLight packed{};
        packed.light = packLight(light);
        packed.shadowSlot = LUMINA_SHADOW_SLOT_NONE;
        const auto index = static_cast<uint32_t>(i);
        if (light.type == scene::LightType::Directional) {
            if (!setup.sun) {
                setup.sun = index;
                packed.shadowSlot = 0u;
            } else {
                setup.unshadowed.push_back(lightName(light, i) +
                                           ": unshadowed, only the first directional light (" +
                                           lightName(lights[*setup.sun], *setup.sun) + ") has a shadow map");
            }
        } else if (setup.cubeLights.size() < LUMINA_MAX_SHADOWED_LIGHTS) {
            packed.shadowSlot = static_cast<uint32_t>(setup.cubeLights.size());
            setup.cubeLights.push_back(index);
        } else {
            setup.unshadowed.push_back(lightName(light, i) + ": unshadowed, beyond the " +
                                       std::to_string(LUMINA_MAX_SHADOWED_LIGHTS) +
                                       " shadow-casting point and spot lights");
        }
        setup.lights.push_back(packed);
    }
    return setup;
}

SunShadowFit fitSunShadow(const scene::Bounds& casters, const glm::vec3& direction, uint32_t mapSize) {
    const glm::vec3 forward = glm::normalize(direction);
    // Any axis not parallel to the sun serves as "up"; the map's orientation does not matter.
    const glm::vec3 reference = std::abs(forward.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 right = glm::normalize(glm::cross(forward, reference));
    const glm::vec3 up = glm::cross(right, forward);

    scene::Bounds box = casters;
    if (box.empty()) {
        box.extend(glm::vec3(-1.0f));
        box.extend(glm::vec3(1.0f));
    }
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(-std::numeric_limits<float>::max());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                          (corner & 4) ? box.max.z : box.min.z);
        const glm::vec3 light(glm::dot(p, right), glm::dot(p, up), glm::dot(p, forward));
        lo = glm::min(lo, light);
        hi = glm::max(hi, light);
    }
    // A square map with a margin of two texels on each side, so that PCF taps at the scene's
    // edge stay inside; depth padded by 1% so that nothing sits on the clip planes.
    const float side = std::max({hi.x - lo.x, hi.y - lo.y, 1.0e-6f});
    const float extent = side * float(mapSize) / float(std::max(mapSize, 5u) - 4u);
    const float padding = 0.01f * std::max(hi.z - lo.z, 1.0e-6f);
    const float nearZ = lo.z - padding;
    const float depthRange = hi.z - lo.z + 2.0f * padding;
    const float centreX = 0.5f * (lo.x + hi.x);
    const float centreY = 0.5f * (lo.y + hi.y);
    const float scale = 2.0f / extent;

    SunShadowFit fit;
    fit.viewProjRows[0] = glm::vec4(right * scale, -centreX * scale);
    fit.viewProjRows[1] = glm::vec4(up * scale, -centreY * scale);
    fit.viewProjRows[2] = glm::vec4(forward / depthRange, -nearZ / depthRange);
    fit.viewProjRows[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    fit.texelWorld = extent / float(mapSize);
    fit.depthRange = depthRange;
    return fit;
}

float pointShadowRange(const scene::Light& light, const scene::Bounds& sceneBounds) {
    float farthest = 0.0f;
    if (!sceneBounds.empty()) {
        const glm::vec3 far =
            glm::max(glm::abs(sceneBounds.min - light.position), glm::abs(sceneBounds.max - light.position));
        farthest = glm::length(far);
    }
    // 1% beyond the farthest corner so that the corner itself is inside; never zero.
    const float cover = std::max(farthest * 1.01f, 1.0e-3f);
    return light.range > 0.0f ? std::min(light.range, cover) : cover;
}

} // namespace lumina::gi
