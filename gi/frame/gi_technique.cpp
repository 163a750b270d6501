#include "gi/frame/gi_technique.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) {
        out += (out.empty() ? "" : ", ") + name;
    }
    return out;
}

} // namespace

GiTechnique parseGiTechnique(std::string_view name) {
    if (name == "direct") {
        return GiTechnique::Direct;
    }
    if (name == "lumen") {
        return GiTechnique::Lumen;
    }
    if (name == "ddgi") {
        return GiTechnique::Ddgi;
    }
    if (name == "sh-grid") {
        return GiTechnique::ShGrid;
    }
    throw std::invalid_argument("unknown GI technique '" + std::string(name) + "' (choose " +
                                joined(giTechniqueNames()) + ")");
}

const char* giTechniqueName(GiTechnique technique) {
    switch (technique) {
    case GiTechnique::Lumen:
        return "lumen";
    case GiTechnique::Ddgi:
        return "ddgi";
    case GiTechnique::ShGrid:
        return "sh-grid";
    default:
        return "direct";
    }
}

std::vector<std::string> giTechniqueNames() {
    return {"direct", "lumen", "ddgi", "sh-grid"};
}

LumenSettings lumenPreset(std::string_view preset, const scene::Scene& scene) {
    return lumenPreset(findPreset(preset), scene);
}

float giSceneExtent(const scene::Scene& scene) {
    const scene::Bounds bounds = scene.worldBounds();
    const glm::vec3 extent = bounds.max - bounds.min;
    const float largest = std::max({extent.x, extent.y, extent.z});
    if (!(largest > 0.0f) || !std::isfinite(largest)) {
        throw std::invalid_argument("scene '" + scene.name + "' has no extent: nothing for GI to light");
    }
    return largest;
}

void setMeshSdfResolution(GiSceneSettings& settings, uint32_t voxels, const scene::Scene& scene) {
    if (voxels < kMinMeshSdfResolution || voxels > kMaxMeshSdfResolution) {
        throw std::invalid_argument("mesh SDF resolution " + std::to_string(voxels) + " is outside [" +
                                    std::to_string(kMinMeshSdfResolution) + ", " +
                                    std::to_string(kMaxMeshSdfResolution) + "]");
    }
    settings.sdf.mesh.resolution = voxels;
    // SDF hits lie up to about half a mesh-SDF voxel off the surface; a mesh spans at most the
    // scene, so one scene-wide mesh voxel of padding lets every hit find its card.
    settings.cache.minPaddingUnits = giSceneExtent(scene) / float(voxels);
}

void setGlobalSdfResolution(GiSceneSettings& settings, uint32_t voxels) {
    if (voxels < kMinGlobalSdfResolution || voxels > kMaxGlobalSdfResolution) {
        throw std::invalid_argument("global SDF resolution " + std::to_string(voxels) + " is outside [" +
                                    std::to_string(kMinGlobalSdfResolution) + ", " +
                                    std::to_string(kMaxGlobalSdfResolution) + "]");
    }
    settings.sdf.globalResolution = voxels;
    settings.lighting.trace.originOffsetVoxels = float(voxels) / float(kPresetGlobalSdfResolution);
}

GiSceneSettings giScenePreset(const Preset& knobs, const scene::Scene& scene) {
    const float largest = giSceneExtent(scene);
    GiSceneSettings s;
    setGlobalSdfResolution(s, kPresetGlobalSdfResolution);

    s.cache.atlasSize = knobs.atlasSize;
    const double metresPerUnit = scene.units.metresPerUnit > 0.0 ? scene.units.metresPerUnit : 1.0;
    const float detailExtent = std::min(largest, float(kCardDetailExtentMetres / metresPerUnit));
    s.cache.texelsPerUnit = knobs.cardTexelsAcross / detailExtent;
    setMeshSdfResolution(s, 64, scene);
    s.lighting.schedule.tilesPerUpdate =
        std::max(1u, knobs.radiosityTexelsPerFrame / (surface_cache::kTileSize * surface_cache::kTileSize));
    s.lighting.schedule.tolerance = knobs.radiosityTolerance;
    return s;
}

LumenSettings lumenPreset(const Preset& knobs, const scene::Scene& scene) {
    LumenSettings s;
    static_cast<GiSceneSettings&>(s) = giScenePreset(knobs, scene);

    // Medium and high: every ray traced through the mesh SDFs and read from the cards, the far
    // field skipped. The far field's cones saw past the atrium's columns and covered the near
    // field's deficits in the room scenes; with those fixed (docs/gi.md, energy 33.-41.) the whole
    // near field is the more accurate and, without the cones, the cheaper. Low: 15 % of the
    // scene's extent, then the far field (the preset says why).
    s.probes.nearFieldDistance = knobs.nearFieldExtentFraction > 0.0f
                                     ? knobs.nearFieldExtentFraction * giSceneExtent(scene)
                                     : ScreenProbeSettings::kNearFieldWholeTrace;
    s.probes.probeSpacing = knobs.probeSpacing;
    s.probes.raysPerProbe = knobs.raysPerProbe;
    s.probes.probeHistoryBlend = knobs.probeHistoryBlend;
    s.probes.screenHistoryBlend = knobs.screenHistoryBlend;
    return s;
}

} // namespace lumina::gi
