#pragma once
// Packs the distance volumes of many meshes into one 3D texture and the table that finds
// them (shaders/common/sdf_shared.h), and samples it on the CPU exactly as
// shaders/common/sdf_sampling.hlsli does on the GPU (the reference for GPU tests).
#include "gi/sdf/mesh_sdf.h"
#include "shaders/common/sdf_shared.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lumina::sdf {

enum class SdfTexelFormat : uint32_t {
    R16F, // IEEE half, stored as uint16_t bits (round to nearest even)
    R32F,
};

struct SdfAtlasSettings {
    SdfTexelFormat format = SdfTexelFormat::R16F;
    uint32_t maxDimension = 2048; // per axis: D3D12's 3D texture limit, Vulkan's minimum guarantee
};

// Texels outside every volume (never sampled, by the clamp) hold this, in voxels.
inline constexpr float kSdfEmptyTexel = 1024.0f;

struct SdfAtlas {
    glm::uvec3 dims{0};
    SdfTexelFormat format = SdfTexelFormat::R16F;
    std::vector<uint16_t> texelsR16F;        // filled for R16F: x fastest, then y, then z
    std::vector<float> texelsR32F;           // filled for R32F
    std::vector<gpu::SdfVolumeDesc> volumes; // one per packed MeshSdf, in input order

    size_t texelIndex(uint32_t x, uint32_t y, uint32_t z) const {
        return (size_t(z) * dims.y + y) * dims.x + x;
    }
    // Decoded texel: a distance in voxels of the volume that owns it.
    float texel(uint32_t x, uint32_t y, uint32_t z) const;
    const void* data() const;
    size_t byteSize() const;
    gpu::SdfAtlasInfo info() const;
};

// Shelf packing: volumes sorted by depth then height fill rows along x, rows fill slabs
// along y, slabs stack along z. Throws std::length_error when the atlas would exceed
// maxDimension on an axis.
SdfAtlas packSdfs(std::span<const MeshSdf> sdfs, const SdfAtlasSettings& settings = {});

// Trilinear sample of one volume at a mesh-space point, in mesh units, as the GPU does it:
// the local voxel coordinate is clamped to [0.5, dims - 0.5]. Outside the volume box the
// result is sqrt(d^2 + s^2), d the distance to the box and s the sample at the nearest box
// point q: a lower bound of the true distance (since the mesh lies inside the box, every mesh
// point m has |p - m|^2 >= |p - q|^2 + |q - m|^2), exact where the nearest surface point is
// seen from q straight along the box normal, never below the distance to the box.
float sampleSdf(const SdfAtlas& atlas, uint32_t volume, const glm::vec3& p);

uint16_t floatToHalf(float value);
float halfToFloat(uint16_t bits);

} // namespace lumina::sdf
