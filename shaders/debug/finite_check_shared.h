#ifndef LUMINA_FINITE_CHECK_SHARED_H
#define LUMINA_FINITE_CHECK_SHARED_H
// `lumina render --check-finite` (gi/core/finite_check.h): after each pass, one dispatch per float
// resource the pass wrote counts the values that are NaN or +-Inf into one slot of a counter
// buffer; the CPU reads the slots back after the frame and names the first pass whose slot is
// not zero.

#include "../common/shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

// Threads per group edge: 8x8 for 2D textures and arrays (one layer per group z), 4x4x4 for 3D
// textures, 64 for buffers.
#define LUMINA_FINITE_CHECK_GROUP_2D 8
#define LUMINA_FINITE_CHECK_GROUP_3D 4
#define LUMINA_FINITE_CHECK_GROUP_1D 64

// Push constants of every finite-check kernel.
struct FiniteCheckConstants {
    uint4 extent; // x, y, z: width, height, depth or layers (a buffer: float4 elements, 1, 1); w: mip
    uint4 slot;   // x: the counter slot this check adds to; yzw: padding
};
LUMINA_STATIC_ASSERT_SIZE(FiniteCheckConstants, 32);

LUMINA_GPU_NAMESPACE_END

#endif
