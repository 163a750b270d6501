#include "gi/frame/gi_technique.h"

#include <algorithm>
#include <stdexcept>

namespace lumina::gi {

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) {
        out += (out.empty() ? "" : ", ") + name;
    }
    return out;
}

// What varies between presets; everything else is the subsystems' defaults.
struct PresetKnobs {
    const char* name;
    uint32_t atlasSize;       // surface-cache atlas side (texels)
    float cardTexelsAcross;   // card texels across the scene's largest extent
    uint32_t radiosityTiles;  // radiosity budget: atlas tiles per update
    uint32_t probeSpacing;    // pixels per screen probe edge
    uint32_t raysPerProbe;    // screen-probe rays
    float probeHistoryBlend;  // weight of the new frame in the probe history
    float screenHistoryBlend; // ... in the full-resolution temporal filter
};

constexpr PresetKnobs kPresets[] = {
    {"low", 1024, 128.0f, 64, 16, 32, 0.15f, 0.3f},
    {"medium", 2048, 256.0f, 256, 8, 64, 0.1f, 0.2f},
    {"high", 4096, 512.0f, 1024, 8, 128, 0.1f, 0.2f},
};

} // namespace

GiTechnique parseGiTechnique(std::string_view name) {
    if (name == "direct") {
        return GiTechnique::Direct;
    }
    if (name == "lumen") {
        return GiTechnique::Lumen;
    }
    throw std::invalid_argument("unknown GI technique '" + std::string(name) + "' (choose " +
                                joined(giTechniqueNames()) + ")");
}

const char* giTechniqueName(GiTechnique technique) {
    return technique == GiTechnique::Lumen ? "lumen" : "direct";
}

std::vector<std::string> giTechniqueNames() {
    return {"direct", "lumen"};
}

std::vector<std::string> lumenPresetNames() {
    std::vector<std::string> names;
    for (const PresetKnobs& knobs : kPresets) {
        names.emplace_back(knobs.name);
    }
    return names;
}

LumenSettings lumenPreset(std::string_view preset, const scene::Scene& scene) {
    const auto* knobs = std::find_if(std::begin(kPresets), std::end(kPresets),
                                     [&](const PresetKnobs& k) { return preset == k.name; });
    if (knobs == std::end(kPresets)) {
        throw std::invalid_argument("unknown lumen preset '" + std::string(preset) + "' (choose " +
                                    joined(lumenPresetNames()) + ")");
    }
    const scene::Bounds bounds = scene.worldBounds();
    const glm::vec3 extent = bounds.max - bounds.min;
    const float largest = std::max({extent.x, extent.y, extent.z});
    if (!(largest > 0.0f) || !std::isfinite(largest)) {
        throw std::invalid_argument("scene '" + scene.name + "' has no extent: nothing for GI to light");
    }

    LumenSettings s;
    s.sdf.mesh.resolution = 64;
    s.sdf.globalResolution = 64;

    s.cache.atlasSize = knobs->atlasSize;
    s.cache.texelsPerUnit = knobs->cardTexelsAcross / largest;
    // SDF hits lie up to about half a mesh-SDF voxel off the surface; a mesh spans at most the
    // scene, so one scene-wide mesh voxel of padding lets every hit find its card.
    s.cache.minPaddingUnits = largest / float(s.sdf.mesh.resolution);
    s.lighting.schedule.tilesPerUpdate = knobs->radiosityTiles;

    // Near-field hits read their cards, far ones the coarse voxel lighting. Measured on lavapipe
    // against 4096-spp references (docs/gi.md): a tenth of the scene's extent gave the lowest
    // error in cornell_box_point (relMSE 0.0108; the gather's default, a quarter of the global
    // SDF diagonal, 0.025, a tenth too bright) and open_top_box (0.040 against 0.059).
    s.probes.nearFieldDistance = 0.1f * largest;
    s.probes.probeSpacing = knobs->probeSpacing;
    s.probes.raysPerProbe = knobs->raysPerProbe;
    s.probes.probeHistoryBlend = knobs->probeHistoryBlend;
    s.probes.screenHistoryBlend = knobs->screenHistoryBlend;
    return s;
}

} // namespace lumina::gi
