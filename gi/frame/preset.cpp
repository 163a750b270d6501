#include "gi/frame/preset.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace lumina::gi {
namespace {

// Radiosity budgets are whole 64x64-texel blocks (the atlas tile of earlier releases, kept so
// the figures in docs/gi.md stay comparable): 64, 256 and 1024 of them.
constexpr uint32_t kBlock = 64 * 64;

constexpr Preset kPresets[] = {
    {.name = "low",
     .sunShadowSize = 1024,
     .pointShadowSize = 256,
     .atlasSize = 2048,
     .cardTexelsAcross = 128.0f,
     .radiosityTexelsPerFrame = 64 * kBlock,
     // The light the radiosity leaves out when it stops, maxAlbedo^bounces: each preset leaves
     // less. With one tolerance, high's finer cards lost 0.06 % more than medium's in
     // furnace_0.99 and high was the less accurate (docs/gi.md, energy 37.).
     .radiosityTolerance = 0.002f,
     .probeSpacing = 16,
     .raysPerProbe = 32,
     .probeHistoryBlend = 0.15f,
     .screenHistoryBlend = 0.3f,
     // 15 % of the scene's extent, the far field beyond, whose cones see past the atrium's columns:
     // atrium reads 3.1 % bright at a tenth, 2.8 % at 15 %, 1.0 % at half. Over the whole ray, low's
     // probe history did not come back within 64 frames of a light 1e6 times too bright (the poison
     // stress test: 0.109 off after 72; at a fifth from frame 68), and with the clamp's share 0.6
     // cornell_box_point's light spot read 4.6 % dark (docs/gi.md, energy 41. and 42.).
     .nearFieldExtentFraction = 0.15f,
     .ddgiProbesPerAxis = 8,
     .ddgiRaysPerProbe = 96,
     .shGridProbesPerAxis = 4,
     .shGridFaceSize = 32,
     .shGridProbesPerFrame = 8},
    {.name = "medium",
     .sunShadowSize = 2048,
     .pointShadowSize = 512,
     .atlasSize = 4096,
     .cardTexelsAcross = 256.0f,
     .radiosityTexelsPerFrame = 256 * kBlock,
     .radiosityTolerance = 0.0015f,
     .probeSpacing = 8,
     .raysPerProbe = 64,
     .probeHistoryBlend = 0.1f,
     .screenHistoryBlend = 0.2f,
     .nearFieldExtentFraction = 0.0f,
     .ddgiProbesPerAxis = 16,
     .ddgiRaysPerProbe = 144,
     .shGridProbesPerAxis = 6,
     .shGridFaceSize = 64,
     .shGridProbesPerFrame = 16},
    {.name = "high",
     .sunShadowSize = 4096,
     .pointShadowSize = 1024,
     .atlasSize = 4096,
     .cardTexelsAcross = 512.0f,
     .radiosityTexelsPerFrame = 1024 * kBlock,
     .radiosityTolerance = 0.0005f,
     // Probes every 6 px: at medium's 8 px, once the outlier clamp bounds each ray alike, high's
     // twice the rays a probe left cornell_box no more accurate than medium (docs/gi.md, energy 36.).
     .probeSpacing = 6,
     .raysPerProbe = 128,
     .probeHistoryBlend = 0.1f,
     .screenHistoryBlend = 0.2f,
     .nearFieldExtentFraction = 0.0f,
     .ddgiProbesPerAxis = 16,
     .ddgiRaysPerProbe = 256,
     .shGridProbesPerAxis = 8,
     .shGridFaceSize = 128,
     .shGridProbesPerFrame = 32},
};

} // namespace

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (const Preset& preset : kPresets) {
        names.emplace_back(preset.name);
    }
    return names;
}

const Preset& findPreset(std::string_view name) {
    const auto* found = std::find_if(std::begin(kPresets), std::end(kPresets),
                                     [&](const Preset& p) { return name == p.name; });
    if (found == std::end(kPresets)) {
        std::string choices;
        for (const std::string& n : presetNames()) {
            choices += (choices.empty() ? "" : ", ") + n;
        }
        throw std::invalid_argument("unknown preset '" + std::string(name) + "' (choose " + choices + ")");
    }
    return *found;
}

} // namespace lumina::gi
