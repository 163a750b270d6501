#pragma once
// The GI techniques `lumina render` and `lumina bench` run, and the quality presets of each,
// by name (scene files, --technique, --preset; docs/gi.md):
//
//   direct  the deferred renderer alone: no indirect light (what a user gets without GI)
//   lumen   surface cache with surface radiosity + screen-probe final gather
//   ddgi    probe volumes traced through the same SDFs and surface cache (gi/ddgi/, docs/ddgi.md)
//   sh-grid a grid of L2 SH irradiance probes baked from raster cube maps (gi/sh_grid/,
//           docs/sh_grid.md)
//
//   presets low, medium (default), high: one table for every technique (preset.h).
#include "gi/frame/preset.h"
#include "gi/scene/scene.h"
#include "gi/screen_probes/screen_probe_settings.h"
#include "gi/sdf/scene_sdf_data.h"
#include "gi/surface_cache/surface_cache.h"
#include "gi/surface_cache/surface_cache_settings.h"

#include <string>
#include <string_view>
#include <vector>

namespace lumina::gi {

enum class GiTechnique { Direct, Lumen, Ddgi, ShGrid };

inline constexpr const char* kDefaultTechnique = "lumen";

// "direct", "lumen", "ddgi" or "sh-grid"; std::invalid_argument naming the name and the choices otherwise.
GiTechnique parseGiTechnique(std::string_view name);
const char* giTechniqueName(GiTechnique technique);
std::vector<std::string> giTechniqueNames();

// The SDFs and surface cache every SDF-traced technique builds on (gi_scene_representation.h).
struct GiSceneSettings {
    sdf::SceneSdfSettings sdf;
    surface_cache::SurfaceCacheSettings cache;
    surface_cache::SurfaceLightingSettings lighting;
};

// Everything the lumen technique is built with.
struct LumenSettings : GiSceneSettings {
    ScreenProbeSettings probes;
};

// Cards get their full density (Preset::cardTexelsAcross) over the scene's largest extent, or
// over this many metres in a larger scene (a city): the LOD (surface_cards.h) coarsens what the
// atlas cannot hold at that density, far cards first.
inline constexpr double kCardDetailExtentMetres = 64.0;

// The largest side of the scene's world box; std::invalid_argument when it has none.
float giSceneExtent(const scene::Scene& scene);

// The SDF and surface-cache settings of a preset for `scene`, the same for every technique that
// traces them. std::invalid_argument for a scene with no extent.
GiSceneSettings giScenePreset(const Preset& preset, const scene::Scene& scene);

// Mesh SDFs of `voxels` along each mesh's longest axis (the presets' 64; `lumina render
// --mesh-sdf-resolution`), with the card padding that resolution's hits need.
inline constexpr uint32_t kMinMeshSdfResolution = 8, kMaxMeshSdfResolution = 512;
// The global SDF's voxels along the scene, or per side of each cascade where the scene has them
// (the presets' 64; `lumina render --global-sdf-resolution`), with the radiosity rays' lift kept at
// one voxel of the presets' grid: a finer grid thins the open surfaces' shells by less than its
// voxel, and a lift of its own voxel started rays inside them (sunlit_rooms 16 % bright at 128).
inline constexpr uint32_t kMinGlobalSdfResolution = 16, kMaxGlobalSdfResolution = 256;
inline constexpr uint32_t kPresetGlobalSdfResolution = 64;
void setGlobalSdfResolution(GiSceneSettings& settings, uint32_t voxels);
void setMeshSdfResolution(GiSceneSettings& settings, uint32_t voxels, const scene::Scene& scene);

// A preset for `scene`: lengths scale with the scene's extent (the Cornell box is in
// millimetres, the city in metres), so card texels, card padding and distances follow the
// scene. std::invalid_argument naming the preset and the choices for an unknown name.
LumenSettings lumenPreset(const Preset& preset, const scene::Scene& scene);
LumenSettings lumenPreset(std::string_view preset, const scene::Scene& scene);

} // namespace lumina::gi
