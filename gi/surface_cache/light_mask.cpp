#include "gi/surface_cache/light_mask.h"

#include "shaders/surface_cache/surface_card_shared.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lumina::surface_cache {

bool lightReaches(const scene::Light& light, const bvh::Aabb& box) {
    if (light.type == scene::LightType::Directional) {
        return true;
    }
    if (light.range > 0.0f) {
        const glm::vec3 nearest = glm::clamp(light.position, box.min, box.max);
        const glm::vec3 d = nearest - light.position;
        if (glm::dot(d, d) > light.range * light.range) {
            return false;
        }
    }
    if (light.type == scene::LightType::Spot) {
        // The cone against the box's bounding sphere: reached unless the sphere lies wholly
        // outside the outer cone (angle to its centre less its angular radius beyond the cone).
        const glm::vec3 toCentre = box.centre() - light.position;
        const float distance = glm::length(toCentre);
        const float radius = 0.5f * glm::length(box.size());
        if (distance <= radius) {
            return true;
        }
        const float cosAngle = std::clamp(glm::dot(toCentre / distance, light.direction), -1.0f, 1.0f);
        const float angle = std::acos(cosAngle) - std::asin(radius / distance);
        return angle <= light.outerConeAngle;
    }
    return true;
}

glm::uvec4 lightMask(const bvh::Aabb& worldBounds, std::span<const scene::Light> lights) {
    if (lights.size() > LUMINA_CARD_LIGHT_MASK_BITS) {
        throw std::invalid_argument("surface cache light mask: " + std::to_string(lights.size()) +
                                    " lights, the mask holds " + std::to_string(LUMINA_CARD_LIGHT_MASK_BITS));
    }
    glm::uvec4 mask(0u);
    for (size_t i = 0; i < lights.size(); ++i) {
        if (lightReaches(lights[i], worldBounds)) {
            mask[int(i / 32)] |= 1u << (i % 32);
        }
    }
    return mask;
}

} // namespace lumina::surface_cache
