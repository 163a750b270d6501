#pragma once
// The quality presets: one table for every technique and every user (lumina render, lumina
// bench, the tests, the viewer), so that `--preset low` means the same shadow maps and GI
// settings wherever it is given. docs/gi.md lists the table.
//
//   const Preset& p = findPreset("medium");
//   deferred.sunShadowSize = p.sunShadowSize;   // every technique
//   LumenSettings lumen = lumenPreset(p, scene); // gi_technique.h: lengths scaled to the scene
//   DdgiSettings ddgi = ddgiPreset(p, scene);    // gi/ddgi/ddgi_settings.h
//   ShGridSettings sh = shGridPreset(p, scene);  // gi/sh_grid/sh_grid_settings.h
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::gi {

struct Preset {
    const char* name;
    // Shadows, for every technique.
    uint32_t sunShadowSize;   // texels per side of the sun's shadow map
    uint32_t pointShadowSize; // texels per cube face of a point light's shadow map
    // Lumen.
    uint32_t atlasSize;               // surface-cache atlas side (texels)
    float cardTexelsAcross;           // card texels across the detail extent (gi_technique.h)
    uint32_t radiosityTexelsPerFrame; // radiosity budget: atlas texels updated per frame
    float radiosityTolerance;         // radiosity stops once a further bounce adds less than this
                                      // share of the light (radiosity_schedule.h)
    uint32_t probeSpacing;            // pixels per screen-probe edge
    uint32_t raysPerProbe;            // screen-probe rays
    float probeHistoryBlend;          // weight of the new frame in the probe history
    float screenHistoryBlend;         // ... in the full-resolution temporal filter
    float nearFieldExtentFraction; // screen-probe near field, x the scene's largest extent; 0: the whole ray
    // DDGI (gi/ddgi/ddgi_settings.h).
    uint32_t ddgiProbesPerAxis; // probes along each axis of a volume fitted to the scene (or a cascade)
    uint32_t ddgiRaysPerProbe;  // rays per probe and update, the fixed relocation set included
    // SH probe grid (gi/sh_grid/sh_grid_settings.h).
    uint32_t shGridProbesPerAxis;  // probes along the scene's largest side
    uint32_t shGridFaceSize;       // texels per side of a probe's cube-map faces
    uint32_t shGridProbesPerFrame; // bake budget
};

inline constexpr const char* kDefaultPreset = "medium";

// The preset of that name; std::invalid_argument naming the name and the choices otherwise.
const Preset& findPreset(std::string_view name);
// "low", "medium", "high": cheapest first.
std::vector<std::string> presetNames();

} // namespace lumina::gi
