#ifndef LUMINA_CONVENTIONS_H
#define LUMINA_CONVENTIONS_H
// Lumina's rendering conventions in one place, for the path tracer and the real-time
// renderer alike, so that their images compare pixel for pixel. docs/conventions.md says the
// same at more length; the definitions themselves live where the code uses them:
//
//   world        right-handed, y up (glTF); lengths in scene units (gi/scene/units.h)
//   camera       shaders/common/camera_shared.h: pinhole at the camera position, vertical field
//                of view, image right = cross(forward, up); pixel (x, y) covers
//                [x, x+1) x [y, y+1), centre (x + 0.5, y + 0.5), row 0 at the top; every
//                renderer makes its rays with cameraRayDirection
//   pixel value  the mean radiance over the pixel's footprint (a box filter); the path tracer
//                samples the footprint uniformly, or only the centre when asked
//                (PathTracerSettings::jitter = false, `lumina reference --pixel-centres`)
//   radiance     linear, scene-referred RGB in the units of units.h; no exposure, no tonemap
//   faces        front faces wind counter-clockwise in object space; an instance whose
//                transform mirrors keeps the front on the side its transformed normals point
//                to; surfaces reflect on both sides, emission leaves the front face only unless
//                the material is double-sided (lights_shared.h: emittedRadiance)
//   materials    Lambertian: albedo = baseColor.rgb x base-colour texture (sRGB-decoded);
//                emission = emissive factor x strength x emission texture, as radiance;
//                metallic and roughness are ignored for now
//   normals      shading uses the interpolated vertex normal (object normal x the instance's
//                normal matrix, normalised); light below the geometric surface is not received
//   lights       shaders/common/lights_shared.h: point and spot I / d^2, directional E, KHR_lights_
//                punctual spot cone and range window; the sky is a uniform radiance seen by
//                every ray that escapes
//   luminance    Rec. 709 weights, below (variance and relative errors of luminance)
#include "shared_types.h"

#define LUMINA_LUMINANCE_R 0.2126f
#define LUMINA_LUMINANCE_G 0.7152f
#define LUMINA_LUMINANCE_B 0.0722f

LUMINA_GPU_NAMESPACE_BEGIN

LUMINA_INLINE float luminance(float3 rgb) {
    return LUMINA_LUMINANCE_R * rgb.x + LUMINA_LUMINANCE_G * rgb.y + LUMINA_LUMINANCE_B * rgb.z;
}

LUMINA_GPU_NAMESPACE_END

#endif
