#pragma once
// Lumina's units, one convention for the scene loader, the path tracer and the real-time
// renderer (docs/scenes.md says the same at more length).
//
// Lengths are scene units: the numbers written in the glTF, never rescaled on load.
// Scene::units.metresPerUnit says how long one is (1 for a plain glTF, as glTF specifies
// metres; 0.001 for the Cornell box, written in millimetres). Nothing in the renderer
// depends on it except the conversion of point and spot intensities below.
//
// Light is radiometric. Photometric numbers in files (nits, lux, candela) are taken as
// radiometric ones with a factor of 1: no 683 lm/W, no luminous efficacy, per RGB channel.
//   - emission and sky: radiance, as written (glTF emissive factor x emissive strength);
//   - a directional light's intensity: irradiance on a surface facing it, as written (lux);
//   - a point or spot light's intensity I: irradiance I/d^2 at a distance of d scene units,
//     on a surface facing it. A file gives candela, meaning irradiance I_cd/d_m^2 with d_m in
//     metres; with d_m = d * metresPerUnit the scene intensity is I_cd / metresPerUnit^2.
// So a diffuse surface of albedo rho under irradiance E leaves radiance rho * E / pi, in
// the same units as emission, whatever the scene's length unit.

namespace lumina::scene {

// Scene-unit intensity of a point or spot light given in candela.
inline double pointIntensityFromCandela(double candela, double metresPerUnit) {
    return candela / (metresPerUnit * metresPerUnit);
}

// The inverse, for writing a glTF.
inline double candelaFromPointIntensity(double intensity, double metresPerUnit) {
    return intensity * metresPerUnit * metresPerUnit;
}

} // namespace lumina::scene
