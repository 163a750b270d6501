#include "gi/sdf/sdf_atlas.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace lumina::sdf {

uint16_t floatToHalf(float value) {
    const uint32_t x = std::bit_cast<uint32_t>(value);
    const uint32_t sign = (x >> 16) & 0x8000u;
    const uint32_t magnitude = x & 0x7FFFFFFFu;
    if (magnitude >= 0x7F800000u) { // inf, NaN (kept quiet)
        return uint16_t(sign | 0x7C00u | (magnitude > 0x7F800000u ? 0x200u : 0u));
    }
    if (magnitude >= 0x477FF000u) { // >= 65520 rounds to infinity
        return uint16_t(sign | 0x7C00u);
    }
    if (magnitude < 0x38800000u) { // below 2^-14: a half subnormal, value * 2^24 rounded to even
        const float scaled = std::bit_cast<float>(magnitude) * 16777216.0f;
        return uint16_t(sign | uint32_t(std::nearbyint(scaled)));
    }
    uint32_t h = (magnitude - 0x38000000u) >> 13; // rebias the exponent 127 -> 15, keep 10 mantissa bits
    const uint32_t rest = magnitude & 0x1FFFu;
    if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) {
        ++h; // may carry into the exponent, which is right
    }
    return uint16_t(sign | h);
}

float halfToFloat(uint16_t bits) {
    const uint32_t sign = uint32_t(bits & 0x8000u) << 16;
    const uint32_t exponent = (bits >> 10) & 0x1Fu;
    const uint32_t mantissa = bits & 0x3FFu;
    if (exponent == 0) {
        const float value = float(mantissa) / 16777216.0f; // subnormal: mantissa * 2^-24
        return std::bit_cast<float>(std::bit_cast<uint32_t>(value) | sign);
    }
    if (exponent == 31) {
        return std::bit_cast<float>(sign | 0x7F800000u | (mantissa << 13));
    }
    return std::bit_cast<float>(sign | ((exponent + 112u) << 23) | (mantissa << 13));
}

float SdfAtlas::texel(uint32_t x, uint32_t y, uint32_t z) const {
    const size_t i = texelIndex(x, y, z);
    return format == SdfTexelFormat::R16F ? halfToFloat(texelsR16F[i]) : texelsR32F[i];
}

const void* SdfAtlas::data() const {
    return format == SdfTexelFormat::R16F ? static_cast<const void*>(texelsR16F.data())
                                          : static_cast<const void*>(texelsR32F.data());
}

size_t SdfAtlas::byteSize() const {
    return format == SdfTexelFormat::R16F ? texelsR16F.size() * sizeof(uint16_t)
                                          : texelsR32F.size() * sizeof(float);
}

gpu::SdfAtlasInfo SdfAtlas::info() const {
    gpu::SdfAtlasInfo info{};
    info.invAtlasDims = glm::vec4(1.0f / glm::vec3(glm::max(dims, glm::uvec3(1))), 0.0f);
    info.counts = glm::uvec4(uint32_t(volumes.size()), 0, 0, 0);
    return info;
}

namespace {

// Places volumes (in `order`) in rows along x, rows in slabs along y, slabs along z; returns
// the depth used.
uint32_t shelfPack(std::span<const MeshSdf> sdfs, const std::vector<uint32_t>& order, uint32_t width,
                   uint32_t height, std::vector<glm::uvec3>& offsets) {
    uint32_t x = 0, y = 0, z = 0, rowHeight = 0, slabDepth = 0;
    for (uint32_t i : order) {
        const glm::uvec3 d = sdfs[i].dims;
        if (x + d.x > width) { // next row
            x = 0;
            y += rowHeight;
            rowHeight = 0;
        }
        if (y + std::max(rowHeight, d.y) > height) { // next slab
            x = 0;
            y = 0;
            z += slabDepth;
            rowHeight = 0;
            slabDepth = 0;
        }
        offsets[i] = {x, y, z};
        x += d.x;
        rowHeight = std::max(rowHeight, d.y);
        slabDepth = std::max(slabDepth, d.z);
    }
    return z + slabDepth;
}

} // namespace

SdfAtlas packSdfs(std::span<const MeshSdf> sdfs, const SdfAtlasSettings& settings) {
    SdfAtlas atlas;
    atlas.format = settings.format;
    if (sdfs.empty()) {
        return atlas;
    }
    uint64_t totalVoxels = 0;
    glm::uvec3 largest(0);
    for (const MeshSdf& sdf : sdfs) {
        if (sdf.distances.size() != size_t(sdf.dims.x) * sdf.dims.y * sdf.dims.z || sdf.distances.empty()) {
            throw std::invalid_argument("packSdfs: a volume's distances do not match its dims");
        }
        totalVoxels += uint64_t(sdf.dims.x) * sdf.dims.y * sdf.dims.z;
        largest = glm::max(largest, sdf.dims);
    }
    if (largest.x > settings.maxDimension || largest.y > settings.maxDimension ||
        largest.z > settings.maxDimension) {
        throw std::length_error("packSdfs: a volume is larger than the atlas limit of " +
                                std::to_string(settings.maxDimension));
    }
    std::vector<uint32_t> order(sdfs.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        if (sdfs[a].dims.z != sdfs[b].dims.z) {
            return sdfs[a].dims.z > sdfs[b].dims.z;
        }
        return sdfs[a].dims.y > sdfs[b].dims.y;
    });
    // Width and height start near the cube root of the total (at least the widest volume) and
    // grow until the stack of slabs fits in depth.
    std::vector<glm::uvec3> offsets(sdfs.size());
    uint32_t side = std::max(uint32_t(std::ceil(std::cbrt(double(totalVoxels) * 1.25))), 1u);
    for (;;) {
        const uint32_t width = std::min(std::max(side, largest.x), settings.maxDimension);
        const uint32_t height = std::min(std::max(side, largest.y), settings.maxDimension);
        const uint32_t depth = shelfPack(sdfs, order, width, height, offsets);
        if (depth <= settings.maxDimension) {
            atlas.dims = {width, height, depth};
            break;
        }
        if (width == settings.maxDimension && height == settings.maxDimension) {
            throw std::length_error("packSdfs: " + std::to_string(sdfs.size()) +
                                    " volumes need an atlas of " + std::to_string(width) + "x" +
                                    std::to_string(height) + "x" + std::to_string(depth) +
                                    ", over the limit of " + std::to_string(settings.maxDimension));
        }
        side = side + side / 4 + 1;
    }

    const size_t texelCount = size_t(atlas.dims.x) * atlas.dims.y * atlas.dims.z;
    if (settings.format == SdfTexelFormat::R16F) {
        atlas.texelsR16F.assign(texelCount, floatToHalf(kSdfEmptyTexel));
    } else {
        atlas.texelsR32F.assign(texelCount, kSdfEmptyTexel);
    }
    atlas.volumes.resize(sdfs.size());
    for (size_t i = 0; i < sdfs.size(); ++i) {
        const MeshSdf& sdf = sdfs[i];
        const glm::uvec3 o = offsets[i];
        const float toVoxels = 1.0f / sdf.voxelSize;
        for (uint32_t k = 0; k < sdf.dims.z; ++k) {
            for (uint32_t j = 0; j < sdf.dims.y; ++j) {
                for (uint32_t v = 0; v < sdf.dims.x; ++v) {
                    const float value = sdf.at(v, j, k) / sdf.voxelSize;
                    const size_t t = atlas.texelIndex(o.x + v, o.y + j, o.z + k);
                    if (settings.format == SdfTexelFormat::R16F) {
                        atlas.texelsR16F[t] = floatToHalf(value);
                    } else {
                        atlas.texelsR32F[t] = value;
                    }
                }
            }
        }
        gpu::SdfVolumeDesc& desc = atlas.volumes[i];
        desc.volumeMinAndVoxelSize = glm::vec4(sdf.volumeMin, sdf.voxelSize);
        desc.volumeMaxAndInvVoxelSize = glm::vec4(sdf.volumeMax(), toVoxels);
        desc.atlasOffset = glm::uvec4(o, 0);
        const bool open =
            std::none_of(sdf.distances.begin(), sdf.distances.end(), [](float d) { return d < 0.0f; });
        desc.dims = glm::uvec4(sdf.dims, open ? LUMINA_SDF_VOLUME_OPEN : 0u);
    }
    return atlas;
}

float sampleSdf(const SdfAtlas& atlas, uint32_t volume, const glm::vec3& p) {
    const gpu::SdfVolumeDesc& desc = atlas.volumes.at(volume);
    const glm::vec3 boxMin(desc.volumeMinAndVoxelSize), boxMax(desc.volumeMaxAndInvVoxelSize);
    const glm::vec3 inBox = glm::clamp(p, boxMin, boxMax);
    const glm::vec3 dims(desc.dims);
    // Texel centres sit at local + 0.5: shift by half a voxel for the lattice the weights use.
    const glm::vec3 local =
        glm::clamp((inBox - boxMin) * desc.volumeMaxAndInvVoxelSize.w, glm::vec3(0.5f), dims - 0.5f) - 0.5f;
    const glm::uvec3 base = glm::min(glm::uvec3(local), glm::uvec3(desc.dims) - 1u);
    const glm::vec3 f = local - glm::vec3(base);
    const glm::uvec3 next = glm::min(base + 1u, glm::uvec3(desc.dims) - 1u);
    const glm::uvec3 o(desc.atlasOffset);
    auto t = [&](uint32_t x, uint32_t y, uint32_t z) { return atlas.texel(o.x + x, o.y + y, o.z + z); };
    const float c00 = glm::mix(t(base.x, base.y, base.z), t(next.x, base.y, base.z), f.x);
    const float c10 = glm::mix(t(base.x, next.y, base.z), t(next.x, next.y, base.z), f.x);
    const float c01 = glm::mix(t(base.x, base.y, next.z), t(next.x, base.y, next.z), f.x);
    const float c11 = glm::mix(t(base.x, next.y, next.z), t(next.x, next.y, next.z), f.x);
    const float c0 = glm::mix(c00, c10, f.y);
    const float c1 = glm::mix(c01, c11, f.y);
    const float sample = glm::mix(c0, c1, f.z) * desc.volumeMinAndVoxelSize.w;
    // Outside the box: q = inBox is p's projection onto the box, so for every mesh point m in
    // the box (p - q).(m - q) <= 0 and |p - m|^2 >= |p - q|^2 + |q - m|^2 >= |p - q|^2 + d(q)^2.
    const glm::vec3 outside = p - inBox;
    const float outsideSquared = glm::dot(outside, outside);
    if (outsideSquared > 0.0f) {
        const float atBox = std::max(sample, 0.0f);
        return std::sqrt(outsideSquared + atBox * atBox);
    }
    return sample;
}

} // namespace lumina::sdf
