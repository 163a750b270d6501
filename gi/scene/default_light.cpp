#include "gi/scene/default_light.h"

#include <algorithm>
#include <cmath>

namespace lumina::scene {

glm::vec3 defaultSunDirection() {
    const float elevation = glm::radians(kDefaultSunElevationDegrees);
    const float azimuth = glm::radians(kDefaultSunAzimuthDegrees);
    const glm::vec3 towardsSun(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                               std::cos(elevation) * std::cos(azimuth));
    return -towardsSun;
}

bool sceneHasLight(const Scene& scene) {
    const bool emissive = std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
        return m.emission.x + m.emission.y + m.emission.z > 0.0f;
    });
    const bool lit = std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& light) {
        const glm::vec3 s = light.strength();
        return s.x + s.y + s.z > 0.0f;
    });
    return lit || emissive || scene.hasSky();
}

void addDefaultLight(Scene& scene) {
    scene.lights.push_back(Light{.type = LightType::Directional,
                                 .name = "default sun",
                                 .color = kDefaultSunColor,
                                 .intensity = kDefaultSunIrradiance,
                                 .direction = defaultSunDirection()});
    if (!scene.hasSky()) {
        scene.skyEnvironment.reset();
        scene.sky = kDefaultSky;
    }
    scene.defaultLight = true;
}

} // namespace lumina::scene
