#ifndef LUMINA_CONSTANTS_SHARED_H
#define LUMINA_CONSTANTS_SHARED_H
// The numbers every kernel and its C++ side share, defined once for both languages: plain
// macros with float (f) or uint (u) literals, which C++, glslang, DXC and vkd3d-shader all read
// the same way. A kernel includes "common/constants_shared.h", a shared header
// "../common/constants_shared.h", C++ "shaders/common/constants_shared.h".

// --- pi ---------------------------------------------------------------------------------
// A Lambertian surface of albedo rho leaves rho / pi of its irradiance as radiance.
#define LUMINA_PI 3.14159265358979f
#define LUMINA_INV_PI 0.318309886183791f

// --- half floats ------------------------------------------------------------------------
// The largest finite half float: radiance written to half-float layers is clamped below it
// (docs/architecture.md, "Numerical hygiene"), since anything above becomes infinity.
#define LUMINA_HALF_MAX 65504.0f

// --- real spherical harmonics up to L2 --------------------------------------------------
// Sloan, "Stupid Spherical Harmonics Tricks" (2008); index l * (l + 1) + m.
#define LUMINA_SH_Y00 0.282094792f  // 1 / (2 sqrt(pi))
#define LUMINA_SH_Y1 0.488602512f   // sqrt(3) / (2 sqrt(pi)): y, z, x
#define LUMINA_SH_Y2_XY 1.092548431f // sqrt(15) / (2 sqrt(pi)): xy, yz, xz
#define LUMINA_SH_Y20 0.315391565f  // sqrt(5) / (4 sqrt(pi)): 3 z^2 - 1
#define LUMINA_SH_Y22 0.546274215f  // sqrt(15) / (4 sqrt(pi)): x^2 - y^2
// The clamped cosine's zonal factors A_l (Ramamoorthi and Hanrahan 2001): irradiance
// E(n) = sum A_l L_lm Y_lm(n).
#define LUMINA_SH_COSINE_A0 3.14159265358979f  // pi
#define LUMINA_SH_COSINE_A1 2.09439510239320f  // 2 pi / 3
#define LUMINA_SH_COSINE_A2 0.785398163397448f // pi / 4

// --- thread groups ----------------------------------------------------------------------
// Kernels over pixels (or another 2D grid) run 8 x 8 groups, kernels over a list 64 threads,
// kernels over a 3D volume 4 x 4 x 4. The C++ side dispatches with the same macros.
#define LUMINA_SCREEN_GROUP_SIZE 8u
#define LUMINA_LINEAR_GROUP_SIZE 64u
#define LUMINA_VOLUME_GROUP_SIZE 4u

#endif
