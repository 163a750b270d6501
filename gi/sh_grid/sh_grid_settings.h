#pragma once
// Settings of the SH probe grid technique (docs/sh_grid.md) and where its probes go.
//
//   ShGridSettings s = shGridPreset("medium", scene); // from the one preset table (preset.h)
//   ShGridLayout grid = fitShGrid(s, scene.worldBounds());
#include "gi/frame/preset.h"
#include "gi/scene/scene.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <string_view>

namespace lumina::gi {

struct ShGridSettings {
    // Probes along the scene box's largest side; the shorter sides get proportionally fewer
    // (at least 2). probeCounts overrides when not zero.
    uint32_t probesPerAxis = 6;
    glm::uvec3 probeCounts{0};
    uint32_t faceSize = 32;       // texels per side of a probe's cube-map faces
    uint32_t probesPerFrame = 16; // bake budget: probes baked in one frame at most
    // Bakes of every probe after a change (and at the start). Each bake's surfaces also send the
    // grid's own irradiance (when `bounce`), so sweep k adds the (k-1)-th bounce.
    uint32_t sweeps = 3;
    bool bounce = true;
    // Hann window over the SH bands against ringing: band l is scaled by
    // (1 + cos(pi l / ringingWindow)) / 2. 0: off (no scaling).
    float ringingWindow = 0.0f;
    // A grid saved by an earlier run (sh_grid_file.h) for this scene and grid: its probes are
    // used as they are and nothing is baked until the scene changes. Empty: bake.
    std::string loadPath;

    // std::invalid_argument naming the setting.
    void validate() const;
};

// The probes: probe (x, y, z) at origin + spacing * (x, y, z), counts per axis.
struct ShGridLayout {
    glm::vec3 origin{0.0f};
    glm::vec3 spacing{1.0f};
    glm::uvec3 counts{2};

    uint32_t probes() const { return counts.x * counts.y * counts.z; }
    glm::uvec3 cell(uint32_t index) const;
    glm::vec3 position(uint32_t index) const;
};

// Probes at the centres of counts^3 equal cells of `box`: none lies on the box's walls.
ShGridLayout fitShGrid(const ShGridSettings& settings, const scene::Bounds& box);

// The window's factors on bands 1 and 2 (1 and 1 when off).
glm::vec2 shGridWindow(float ringingWindow);

ShGridSettings shGridPreset(const Preset& preset, const scene::Scene& scene);
ShGridSettings shGridPreset(std::string_view preset, const scene::Scene& scene);

} // namespace lumina::gi
