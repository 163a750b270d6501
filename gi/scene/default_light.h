#pragma once
// The default light: a scene that brings no light of any kind (no punctual or directional
// light, no emissive material, a black sky) would render black, so the loader gives it a sun
// and a sky (LoadOptions::defaultLight; `--no-default-light` turns it off). docs/scenes.md
// states the rule and the values.
#include "gi/scene/scene.h"

namespace lumina::scene {

// A sun 55 degrees above the horizon, from the +x +z quarter (the side a camera framing the
// bounds from +z looks at, lighting the front and one side of what it frames): irradiance 3,
// which leaves a white (0.8) surface facing it at radiance 0.76, about 0.75 of full scale
// after the ACES tonemap at exposure 0.
inline constexpr float kDefaultSunElevationDegrees = 55.0f;
inline constexpr float kDefaultSunAzimuthDegrees = 40.0f; // from +z towards +x
inline constexpr float kDefaultSunIrradiance = 3.0f;
inline const glm::vec3 kDefaultSunColor{1.0f, 0.96f, 0.9f};
// A pale blue sky: irradiance pi x 0.3 (about 1) on a surface facing up, a third of the sun's,
// so shadowed sides stay readable under GI; the background shows it at about half scale.
inline const glm::vec3 kDefaultSky{0.25f, 0.3f, 0.36f};

// Whether any light reaches the scene: a light, an emissive material or a sky.
bool sceneHasLight(const Scene& scene);

// The default sun (a directional light named "default sun") and, when the sky is black, the
// default uniform sky; sets Scene::defaultLight.
void addDefaultLight(Scene& scene);

// Where the default sun's light travels (unit).
glm::vec3 defaultSunDirection();

} // namespace lumina::scene
