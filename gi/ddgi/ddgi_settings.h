#pragma once
// Everything the DDGI technique is built with (docs/ddgi.md), and its preset: the SDFs and
// surface cache it traces (the same settings lumen uses), and its probe volumes.
//
//   DdgiSettings s = ddgiPreset("medium", scene);  // 16^3 probes fitted to the scene, 144 rays
//   s.probeCounts = {8, 4, 8};                     // or spacing, explicit volumes, cascades
#include "gi/frame/gi_technique.h"
#include "gi/frame/preset.h"
#include "gi/scene/scene.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <string_view>
#include <vector>

namespace lumina::gi {

// A volume placed by hand (a scene file's "ddgi" block, --ddgi-volume): probes at the cell centres
// of `counts` cells dividing the box.
struct DdgiVolumeBox {
    scene::Bounds box;
    glm::uvec3 counts{16};
};

struct DdgiSettings : GiSceneSettings {
    // Where the probes are, first that applies: `volumes` as given; `cascades` camera-centred
    // volumes of probeCounts probes, the finest `cascadeSpacing` apart, each next one twice as
    // wide; else one volume of probeCounts fitted to the scene's box (probes at cell centres).
    std::vector<DdgiVolumeBox> volumes;
    uint32_t cascades = 0;
    float cascadeSpacing = 0.0f; // world units
    glm::uvec3 probeCounts{16};
    // Rays per probe and update, LUMINA_DDGI_FIXED_RAYS of them the fixed relocation set.
    uint32_t raysPerProbe = 144;
    // Share of history kept each update, and after a large change (the new irradiance below the
    // stored by more than largeChangeRatio: a light switched off, an occluder moved in).
    float hysteresis = 0.97f;
    float changedHysteresis = 0.5f;
    float largeChangeRatio = 4.0f;
    // Exponent of the cosine that weights rays into the distance map (sharp: the distances near d).
    float distanceSharpness = 50.0f;
    // Sampling biases, in fractions of the volume's smallest spacing.
    float normalBias = 0.1f;
    float viewBias = 0.3f;
    // Relocation and classification.
    bool relocation = true;
    bool classification = true;
    float backfaceFraction = 0.25f;    // of the fixed rays: more back-face hits is inside geometry
    float minFrontfaceDistance = 0.2f; // of the smallest spacing: a front face nearer moves the probe
    float maxOffset = 0.45f;           // of a cell per axis
    // Mesh SDFs up to this distance, the global SDF beyond (0: the mesh SDFs all the way).
    float nearFieldDistance = 0.0f;
    uint32_t seed = 1; // of the per-update ray rotations

    // std::invalid_argument naming the first bad value.
    void validate() const;
};

// Scenes larger than this (metres, their largest side) get camera-centred cascades instead of one
// fitted volume: a 16^3 volume over a 2 km city is a probe every 130 m.
inline constexpr double kDdgiCascadeSceneMetres = 200.0;
// How many cascades such scenes get, and their finest spacing: wide enough that the coarsest
// cascade reaches across the whole scene from wherever the camera is (twice the scene's largest
// side), at least this many metres (--ddgi-cascades without a --ddgi-spacing on a small scene).
inline constexpr uint32_t kDdgiDefaultCascades = 3;
inline constexpr double kDdgiCascadeSpacingMetres = 2.0;

// With cascades, rays read the mesh SDFs for this many finest-cascade cells and the global SDF
// beyond (a city's thousands of instances would make whole mesh-SDF traces slow).
inline constexpr float kDdgiCascadeNearFieldCells = 4.0f;

// The finest cascade's spacing for `cascades` cascades of `probesPerAxis` over `scene` (scene units).
float ddgiCascadeSpacing(const scene::Scene& scene, uint32_t cascades, uint32_t probesPerAxis);

// Updates after which a probe's history keeps less than 2% of any one earlier update's weight
// (hysteresis^n < 0.02): what `lumina render` runs after the surface cache converged.
uint32_t ddgiSettleUpdates(float hysteresis);

// The preset's probe counts and rays for `scene` (gi_technique.h's scaling for the SDFs and
// surface cache); cascades for a scene larger than kDdgiCascadeSceneMetres. std::invalid_argument
// for an unknown preset or a scene with no extent.
DdgiSettings ddgiPreset(const Preset& preset, const scene::Scene& scene);
DdgiSettings ddgiPreset(std::string_view preset, const scene::Scene& scene);

} // namespace lumina::gi
