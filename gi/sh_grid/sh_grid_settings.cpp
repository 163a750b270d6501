#include "gi/sh_grid/sh_grid_settings.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

// Probes per frame and probes in all: one probe's bake records 19 passes, and the grid's buffer
// is addressed with 32-bit indices.
constexpr uint32_t kMaxProbesPerFrame = 256;
constexpr uint32_t kMaxProbes = 1u << 20;
constexpr uint32_t kMaxFaceSize = 512;

} // namespace

void ShGridSettings::validate() const {
    const auto fail = [](const std::string& what) { throw std::invalid_argument("sh-grid: " + what); };
    if (probeCounts == glm::uvec3(0)) {
        if (probesPerAxis < 2) {
            fail("probes per axis " + std::to_string(probesPerAxis) + " (at least 2)");
        }
    } else if (glm::any(glm::lessThan(probeCounts, glm::uvec3(2)))) {
        fail("probe counts must be at least 2 along every axis");
    }
    const uint64_t most = probeCounts == glm::uvec3(0)
                              ? uint64_t(probesPerAxis) * probesPerAxis * probesPerAxis
                              : uint64_t(probeCounts.x) * probeCounts.y * probeCounts.z;
    if (most > kMaxProbes) {
        fail(std::to_string(most) + " probes (at most " + std::to_string(kMaxProbes) + ")");
    }
    if (faceSize < 8 || faceSize > kMaxFaceSize) {
        fail("face size " + std::to_string(faceSize) + " (8 to " + std::to_string(kMaxFaceSize) + ")");
    }
    if (probesPerFrame == 0 || probesPerFrame > kMaxProbesPerFrame) {
        fail("probes per frame " + std::to_string(probesPerFrame) + " (1 to " +
             std::to_string(kMaxProbesPerFrame) + ")");
    }
    if (sweeps == 0) {
        fail("sweeps must be at least 1");
    }
    if (!std::isfinite(ringingWindow) || ringingWindow < 0.0f ||
        (ringingWindow > 0.0f && ringingWindow <= 2.0f)) {
        fail("ringing window " + std::to_string(ringingWindow) + " (0: off, else above 2 bands)");
    }
}

glm::uvec3 ShGridLayout::cell(uint32_t index) const {
    return {index % counts.x, (index / counts.x) % counts.y, index / (counts.x * counts.y)};
}

glm::vec3 ShGridLayout::position(uint32_t index) const {
    return origin + spacing * glm::vec3(cell(index));
}

ShGridLayout fitShGrid(const ShGridSettings& settings, const scene::Bounds& box) {
    settings.validate();
    const glm::vec3 extent = box.max - box.min;
    const float largest = std::max({extent.x, extent.y, extent.z});
    if (!(largest > 0.0f) || !std::isfinite(largest)) {
        throw std::invalid_argument("sh-grid: the scene has no extent to place probes in");
    }
    ShGridLayout layout;
    layout.counts = settings.probeCounts;
    if (layout.counts == glm::uvec3(0)) {
        for (int a = 0; a < 3; ++a) {
            const float share = extent[a] / largest;
            layout.counts[a] = std::max(2u, uint32_t(std::lround(float(settings.probesPerAxis) * share)));
        }
    }
    // A flat side (a floor plane alone) still gets cells of the largest side's probe spacing.
    const glm::vec3 size = glm::max(extent, glm::vec3(largest / float(settings.probesPerAxis)));
    const glm::vec3 centre = 0.5f * (box.min + box.max);
    layout.spacing = size / glm::vec3(layout.counts);
    layout.origin = centre - 0.5f * size + 0.5f * layout.spacing;
    return layout;
}

glm::vec2 shGridWindow(float ringingWindow) {
    if (ringingWindow <= 0.0f) {
        return glm::vec2(1.0f);
    }
    const auto hann = [&](float band) {
        return 0.5f * (1.0f + std::cos(std::numbers::pi_v<float> * band / ringingWindow));
    };
    return {hann(1.0f), hann(2.0f)};
}

ShGridSettings shGridPreset(const Preset& preset, const scene::Scene&) {
    ShGridSettings s;
    s.probesPerAxis = preset.shGridProbesPerAxis;
    s.faceSize = preset.shGridFaceSize;
    s.probesPerFrame = preset.shGridProbesPerFrame;
    return s;
}

ShGridSettings shGridPreset(std::string_view preset, const scene::Scene& scene) {
    return shGridPreset(findPreset(preset), scene);
}

} // namespace lumina::gi
