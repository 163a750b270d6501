#pragma once
// The scene's lights as the deferred renderer uses them: packed for the GPU in the shared
// light model (shaders/common/lights_shared.h, packed by gi/pathtracer/light_packing.h so that
// both renderers agree), with shadow slots handed out (the first directional light is the sun and gets the
// shadow map; the first LUMINA_MAX_SHADOWED_LIGHTS point and spot lights get a cube each), and the shadow
// projections fitted to the scene.
#include "gi/scene/scene.h"
#include "shaders/deferred/deferred_shared.h"

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lumina::gi {

struct LightSetup {
    std::vector<gpu::DeferredLight> lights; // every light, in scene order, with its shadow slot
    std::optional<uint32_t> sun;            // the light with the sun shadow map
    std::vector<uint32_t> cubeLights;       // lights with a cube shadow map, in cube order
    std::vector<std::string> unshadowed;    // one line per light that casts no shadow, and why
};

LightSetup setupLights(std::span<const scene::Light> lights);

// The sun's orthographic projection, fitted around `casters` so that every caster and every
// receiver inside them lands in the map.
struct SunShadowFit {
    std::array<glm::vec4, 4> viewProjRows{}; // world -> clip: x right, y up, depth 0 nearest the sun
    float texelWorld = 0.0f;                 // world size of one texel
    float depthRange = 0.0f;                 // world distance from depth 0 to depth 1
};

SunShadowFit fitSunShadow(const scene::Bounds& casters, const glm::vec3& direction, uint32_t mapSize);

// The distance a point or spot light's cube map covers: its range when it has one, clipped to
// the farthest corner of the scene (which is also the cover of an unlimited light).
float pointShadowRange(const scene::Light& light, const scene::Bounds& sceneBounds);

} // namespace lumina::gi
