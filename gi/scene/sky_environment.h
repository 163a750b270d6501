#pragma once
// Environment skies: reading an equirectangular EXR into a SkyEnvironment (scene.h has the
// direction convention) and looking it up on the CPU exactly as shaders/common/sky_sampling.hlsli
// does on the GPU (bilinear, wrapping in longitude, clamped at the poles).
#include "gi/scene/scene.h"

#include <cstdint>
#include <filesystem>

namespace lumina::scene {

// Largest environment accepted: a 16384 x 8192 latitude-longitude map, at most 2^25 texels
// (512 MiB as the RGBA32F texture every renderer binds).
inline constexpr uint32_t kMaxSkyWidth = 16384;
inline constexpr uint32_t kMaxSkyHeight = 8192;
inline constexpr uint64_t kMaxSkyTexels = uint64_t(1) << 25;

// The EXR's R, G and B channels times `intensity`. A SceneError names the file and the problem:
// missing, not an EXR, without R/G/B, too large, a NaN, infinite or negative texel (with its
// position), an intensity that is negative or not finite, or texels that overflow once scaled.
SkyEnvironment readSkyEnvironment(const std::filesystem::path& file, float intensity = 1.0f);

// Where `direction` (unit) falls in the map, in texels: x in [0, width), y in [0, height).
glm::vec2 skyTexelCoordinates(const SkyEnvironment& sky, const glm::vec3& direction);

// The radiance arriving from `direction` (unit): the environment's, else the uniform sky.
glm::vec3 skyRadiance(const Scene& scene, const glm::vec3& direction);

} // namespace lumina::scene
