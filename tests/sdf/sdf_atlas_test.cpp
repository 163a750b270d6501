#include "gi/sdf/sdf_atlas.h"
#include "tests/bvh/test_meshes.h"
#include "tests/sdf/sdf_test_util.h"

#include <bit>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <stdexcept>

namespace lumina::sdf {
namespace {

// A synthetic volume: a sphere's distance over arbitrary dims, so packing can be checked
// without building.
MeshSdf syntheticVolume(glm::uvec3 dims, glm::vec3 volumeMin, float voxelSize) {
    MeshSdf sdf;
    sdf.dims = dims;
    sdf.volumeMin = volumeMin;
    sdf.voxelSize = voxelSize;
    sdf.distances.resize(size_t(dims.x) * dims.y * dims.z);
    const glm::vec3 centre = volumeMin + 0.5f * glm::vec3(dims) * voxelSize;
    for (uint32_t z = 0; z < dims.z; ++z) {
        for (uint32_t y = 0; y < dims.y; ++y) {
            for (uint32_t x = 0; x < dims.x; ++x) {
                sdf.distances[sdf.voxelIndex(x, y, z)] =
                    test::sphereDistance(sdf.voxelCentre(x, y, z), centre, 0.3f * float(dims.x) * voxelSize);
            }
        }
    }
    return sdf;
}

std::vector<MeshSdf> someVolumes() {
    std::vector<MeshSdf> sdfs;
    std::mt19937 rng(4);
    std::uniform_int_distribution<uint32_t> dim(4, 40);
    std::uniform_real_distribution<float> pos(-5.0f, 5.0f), size(0.01f, 0.5f);
    for (int i = 0; i < 23; ++i) {
        sdfs.push_back(
            syntheticVolume({dim(rng), dim(rng), dim(rng)}, {pos(rng), pos(rng), pos(rng)}, size(rng)));
    }
    return sdfs;
}

TEST(HalfFloat, ConvertsLikeIeee) {
    EXPECT_EQ(floatToHalf(0.0f), 0x0000);
    EXPECT_EQ(floatToHalf(-0.0f), 0x8000);
    EXPECT_EQ(floatToHalf(1.0f), 0x3C00);
    EXPECT_EQ(floatToHalf(-2.0f), 0xC000);
    EXPECT_EQ(floatToHalf(65504.0f), 0x7BFF);
    EXPECT_EQ(floatToHalf(65519.0f), 0x7BFF);
    EXPECT_EQ(floatToHalf(65520.0f), 0x7C00); // rounds to infinity
    EXPECT_EQ(floatToHalf(std::numeric_limits<float>::infinity()), 0x7C00);
    EXPECT_EQ(floatToHalf(std::nanf("")) & 0x7C00, 0x7C00);
    EXPECT_NE(floatToHalf(std::nanf("")) & 0x03FF, 0);
    EXPECT_EQ(floatToHalf(std::ldexp(1.0f, -24)), 0x0001);            // smallest subnormal
    EXPECT_EQ(floatToHalf(std::ldexp(1.0f, -14)), 0x0400);            // smallest normal
    EXPECT_EQ(floatToHalf(1.0f + std::ldexp(1.0f, -11)), 0x3C00);     // tie: to even (down)
    EXPECT_EQ(floatToHalf(1.0f + 3 * std::ldexp(1.0f, -11)), 0x3C02); // tie: to even (up)
    // Every half survives the round trip.
    for (uint32_t h = 0; h < 0x10000; ++h) {
        const float f = halfToFloat(uint16_t(h));
        if (std::isnan(f)) {
            EXPECT_TRUE(std::isnan(halfToFloat(floatToHalf(f))));
            continue;
        }
        ASSERT_EQ(floatToHalf(f), h) << std::hex << h;
    }
    EXPECT_FLOAT_EQ(halfToFloat(0x3555), 0.333251953125f);
}

TEST(SdfAtlas, PackingRoundTripsEveryVoxel) {
    const std::vector<MeshSdf> sdfs = someVolumes();
    for (SdfTexelFormat format : {SdfTexelFormat::R32F, SdfTexelFormat::R16F}) {
        SdfAtlasSettings settings;
        settings.format = format;
        const SdfAtlas atlas = packSdfs(sdfs, settings);
        ASSERT_EQ(atlas.volumes.size(), sdfs.size());
        EXPECT_EQ(atlas.byteSize(), size_t(atlas.dims.x) * atlas.dims.y * atlas.dims.z *
                                        (format == SdfTexelFormat::R16F ? 2 : 4));
        std::vector<int> owner(size_t(atlas.dims.x) * atlas.dims.y * atlas.dims.z, -1);
        for (size_t i = 0; i < sdfs.size(); ++i) {
            const MeshSdf& sdf = sdfs[i];
            const gpu::SdfVolumeDesc& desc = atlas.volumes[i];
            EXPECT_EQ(glm::uvec3(desc.dims), sdf.dims);
            EXPECT_EQ(glm::vec3(desc.volumeMinAndVoxelSize), sdf.volumeMin);
            EXPECT_EQ(desc.volumeMinAndVoxelSize.w, sdf.voxelSize);
            const glm::uvec3 o(desc.atlasOffset);
            ASSERT_TRUE(glm::all(glm::lessThanEqual(o + sdf.dims, atlas.dims)));
            for (uint32_t z = 0; z < sdf.dims.z; ++z) {
                for (uint32_t y = 0; y < sdf.dims.y; ++y) {
                    for (uint32_t x = 0; x < sdf.dims.x; ++x) {
                        int& who = owner[atlas.texelIndex(o.x + x, o.y + y, o.z + z)];
                        ASSERT_EQ(who, -1) << "volumes " << who << " and " << i << " overlap";
                        who = int(i);
                        const float expected = sdf.at(x, y, z) / sdf.voxelSize;
                        const float stored = atlas.texel(o.x + x, o.y + y, o.z + z);
                        if (format == SdfTexelFormat::R32F) {
                            ASSERT_EQ(stored, expected);
                        } else {
                            ASSERT_EQ(stored, halfToFloat(floatToHalf(expected)));
                        }
                        // Sampling at the voxel centre through the table returns the voxel.
                        const float sampled = sampleSdf(atlas, uint32_t(i), sdf.voxelCentre(x, y, z));
                        ASSERT_NEAR(sampled, stored * sdf.voxelSize,
                                    1e-4f * sdf.voxelSize * (1.0f + std::abs(stored)));
                    }
                }
            }
        }
    }
}

TEST(SdfAtlas, SamplingMatchesTheGridAndBoundsOutside) {
    const lumina::test::Mesh sphere = lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 3);
    SdfSettings settings;
    settings.resolution = 24;
    const MeshSdf sdf = buildMeshSdf(sphere.positions, sphere.indices, settings);
    SdfAtlasSettings atlasSettings;
    atlasSettings.format = SdfTexelFormat::R32F;
    const std::vector<MeshSdf> sdfs = {syntheticVolume({5, 6, 7}, {0, 0, 0}, 1.0f), sdf};
    const SdfAtlas atlas = packSdfs(sdfs, atlasSettings);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.15f, 1.15f); // inside the volume box (+-1.2)
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 p(u(rng), u(rng), u(rng));
        EXPECT_NEAR(sampleSdf(atlas, 1, p), test::sampleGrid(sdf, p), 1e-5f);
    }
    // Outside the volume box the sample is a lower bound of the true distance.
    std::uniform_real_distribution<float> far(-20.0f, 20.0f);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 p(far(rng), far(rng), far(rng));
        const float exact = test::sphereDistance(p, {0, 0, 0}, 1.0f);
        const float sampled = sampleSdf(atlas, 1, p);
        EXPECT_LE(sampled, exact + 0.5f * std::sqrt(3.0f) * sdf.voxelSize);
        const glm::vec3 q = glm::clamp(p, sdf.volumeMin, sdf.volumeMax());
        EXPECT_GE(sampled, glm::length(p - q) - 1e-5f); // at least the distance to the volume
        if (glm::length(p) > 3.0f) {                    // far away the bound is not far off
            EXPECT_GT(sampled, 0.6f * exact);
        }
    }
}

TEST(SdfAtlas, EmptyAndTooLarge) {
    EXPECT_TRUE(packSdfs({}).volumes.empty());
    std::vector<MeshSdf> many(40, syntheticVolume({16, 16, 16}, {0, 0, 0}, 1.0f));
    SdfAtlasSettings settings;
    settings.maxDimension = 32;
    EXPECT_THROW(packSdfs(many, settings), std::length_error);
    settings.maxDimension = 64;
    const SdfAtlas atlas = packSdfs(many, settings);
    EXPECT_LE(atlas.dims.z, 64u);
    const gpu::SdfAtlasInfo info = atlas.info();
    EXPECT_EQ(info.counts.x, 40u);
    EXPECT_FLOAT_EQ(info.invAtlasDims.x, 1.0f / float(atlas.dims.x));
}

} // namespace
} // namespace lumina::sdf
