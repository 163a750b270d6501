#ifndef LUMINA_SHARED_TYPES_H
#define LUMINA_SHARED_TYPES_H
// The tiny macro layer that lets one header declare GPU structs (and small pure functions)
// for both C++ and HLSL. In C++ the HLSL vector types are glm types inside namespace
// lumina::gpu; in HLSL everything below is native and the macros vanish.
//
//   LUMINA_GPU_NAMESPACE_BEGIN / _END  wrap shared declarations (namespace lumina::gpu in C++)
//   LUMINA_INLINE                       `inline` in C++, nothing in HLSL
//   LUMINA_OUT(T) / LUMINA_INOUT(T)     `T&` in C++, `out T` / `inout T` in HLSL
//   LUMINA_UNROLL                       HLSL `[unroll]` before a loop; nothing in C++
//   LUMINA_PRECISE                      HLSL `precise` (no FMA contraction); nothing in C++, where
//                                       ISO mode (-std=c++20) already keeps a*b-c*d uncontracted
//   LUMINA_STATIC_ASSERT_SIZE(T, n)     checks sizeof(T) == n and 16-byte alignment in C++ only
//   LUMINA_STATIC_ASSERT_OFFSET(T, m, n) checks that member m of T starts at byte n, in C++ only
//   luminaReverseBits(v)                reversebits for C++; with LUMINA_DXBC (vkd3d-shader), isnan
//                                       and reversebits themselves are defined at the end
//
// Rules for shared structs (docs/architecture.md, "Shared structs"): members fill whole 16-byte rows
// (a 4-vector; a 3-vector and a scalar; a 2-vector and two scalars or a 2-vector; four scalars),
// a vector starts its row, unused lanes are named padding members, so std140/std430 (glslang,
// DXC), D3D's cbuffer and structured-buffer packing (vkd3d, DXC) and C++ agree; uint instead of
// bool, no matrices. Shared functions avoid swizzles (glm has none without GLM_FORCE_SWIZZLE) and
// use only the intrinsics mirrored here.

#ifdef __cplusplus

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#define LUMINA_GPU_NAMESPACE_BEGIN namespace lumina::gpu {
#define LUMINA_GPU_NAMESPACE_END }
#define LUMINA_INLINE inline
#define LUMINA_OUT(T) T&
#define LUMINA_INOUT(T) T&
#define LUMINA_PRECISE
#define LUMINA_UNROLL
#define LUMINA_STATIC_ASSERT_SIZE(T, n)                                                                      \
    static_assert(sizeof(T) == (n), #T ": size must match the HLSL layout");                                 \
    static_assert(sizeof(T) % 16 == 0, #T ": GPU structs are 16-byte multiples")
#define LUMINA_STATIC_ASSERT_OFFSET(T, member, n)                                                            \
    static_assert(offsetof(T, member) == (n), #T "::" #member ": offset must match the HLSL layout")

namespace lumina::gpu {

using uint = uint32_t;
using float2 = glm::vec2;
using float3 = glm::vec3;
using float4 = glm::vec4;
using uint2 = glm::uvec2;
using uint3 = glm::uvec3;
using uint4 = glm::uvec4;
using int3 = glm::ivec3;

inline uint asuint(float x) {
    return std::bit_cast<uint>(x);
}
inline float asfloat(uint x) {
    return std::bit_cast<float>(x);
}
using glm::abs;
using glm::cross;
using glm::dot;
using glm::max;
using glm::min;
using std::sqrt;

} // namespace lumina::gpu

#else // HLSL

#define LUMINA_GPU_NAMESPACE_BEGIN
#define LUMINA_GPU_NAMESPACE_END
#define LUMINA_INLINE
#define LUMINA_OUT(T) out T
#define LUMINA_INOUT(T) inout T
#define LUMINA_PRECISE precise
#define LUMINA_UNROLL [unroll]
#define LUMINA_STATIC_ASSERT_SIZE(T, n)
#define LUMINA_STATIC_ASSERT_OFFSET(T, member, n)

#endif

LUMINA_GPU_NAMESPACE_BEGIN

// reversebits in plain integer arithmetic, for the compilers without it: C++, and
// vkd3d-shader's HLSL compiler (the DXBC build, below).
LUMINA_INLINE uint luminaReverseBits(uint v) {
    v = ((v >> 1u) & 0x55555555u) | ((v & 0x55555555u) << 1u);
    v = ((v >> 2u) & 0x33333333u) | ((v & 0x33333333u) << 2u);
    v = ((v >> 4u) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4u);
    v = ((v >> 8u) & 0x00FF00FFu) | ((v & 0x00FF00FFu) << 8u);
    return (v >> 16u) | (v << 16u);
}

LUMINA_GPU_NAMESPACE_END

// vkd3d-shader's HLSL compiler (LUMINA_DXBC, docs/d3d12.md) lacks isnan and reversebits, and
// cannot emit isinf for shader model 5: the same operations on the bits, for scalars and
// vectors alike, under the intrinsics' names, so kernels call them with every compiler.
#if !defined(__cplusplus) && defined(LUMINA_DXBC)
#define isnan(v) ((asuint(v) & 0x7FFFFFFFu) > 0x7F800000u)
#define isinf(v) ((asuint(v) & 0x7FFFFFFFu) == 0x7F800000u)
#define reversebits(v) luminaReverseBits(v)
#endif

#endif
