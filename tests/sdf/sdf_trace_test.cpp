#include "gi/bvh/bvh_query.h"
#include "gi/sdf/sdf_trace.h"
#include "tests/bvh/test_meshes.h"

#include <gtest/gtest.h>
#include <random>

namespace lumina::sdf {
namespace {

// The CPU twin of the GPU SDF tracing test to come: sphere tracing through the atlas (R16F,
// trilinear) against exact BVH ray casts on the same meshes. Rays start outside each
// mesh's bounding sphere and aim at random points near the mesh, so that about half hit.
//
// Required: hit/miss agreement on >= 99% of rays; every SDF hit point within one voxel of
// the mesh; the hit distance t within one voxel of the BVH's on >= 99% of common hits. (The
// tracer stops 0.1 voxel from the surface, which along a ray meeting a face at grazing
// angle theta is 0.1 / cos(theta) voxels early; and a ray that grazes one part of a mesh
// may count as a hit there for the SDF and pass on to another part for the BVH.)
struct Agreement {
    uint32_t rays = 0, agree = 0, hits = 0, hitsWithinVoxel = 0, pointsOffSurface = 0;
    float worstHitError = 0.0f; // in voxels
};

Agreement compare(const lumina::test::Mesh& mesh, uint32_t rayCount, uint32_t seed) {
    SdfSettings settings;
    settings.resolution = 32;
    const MeshSdf sdf = buildMeshSdf(mesh.positions, mesh.indices, settings);
    const SdfAtlas atlas = packSdfs(std::span<const MeshSdf>(&sdf, 1));
    const bvh::Bvh bvh = bvh::buildBvh(mesh.positions, mesh.indices);

    const glm::vec3 centre = bvh.bounds.centre();
    const float radius = 0.5f * glm::length(bvh.bounds.size());
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Agreement a;
    for (uint32_t i = 0; i < rayCount; ++i) {
        const glm::vec3 origin = centre + 1.5f * radius * lumina::test::randomUnitVector(rng);
        const glm::vec3 target = centre + 0.8f * radius * glm::vec3(u(rng), u(rng), u(rng));
        const glm::vec3 direction = glm::normalize(target - origin);
        bvh::Ray ray;
        ray.origin = origin;
        ray.direction = direction;
        const bvh::RayHit exact = bvh::intersectClosest(bvh, ray);
        const SdfTraceResult traced = traceSdf(atlas, 0, origin, direction);
        ++a.rays;
        a.agree += exact.hit() == traced.hit;
        if (traced.hit) {
            const glm::vec3 p = origin + traced.t * direction;
            a.pointsOffSurface += bvh::closestPoint(bvh, p).distanceSquared > sdf.voxelSize * sdf.voxelSize;
        }
        if (exact.hit() && traced.hit) {
            ++a.hits;
            const float error = std::abs(traced.t - exact.t) / sdf.voxelSize;
            a.worstHitError = std::max(a.worstHitError, error);
            a.hitsWithinVoxel += error <= 1.0f;
        }
    }
    return a;
}

void expectAgreement(const Agreement& a) {
    EXPECT_GE(double(a.agree), 0.99 * double(a.rays)) << a.agree << " of " << a.rays;
    EXPECT_GT(a.hits, a.rays / 5);
    EXPECT_EQ(a.pointsOffSurface, 0u);
    EXPECT_GE(double(a.hitsWithinVoxel), 0.99 * double(a.hits))
        << a.hitsWithinVoxel << " of " << a.hits << "; worst " << a.worstHitError << " voxels";
}

TEST(SdfTrace, SphereAgreesWithBvh) {
    expectAgreement(compare(lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 4), 3000, 1));
}

TEST(SdfTrace, BoxAgreesWithBvh) {
    expectAgreement(compare(lumina::test::makeBox({-1.0f, -0.4f, -0.7f}, {0.8f, 0.6f, 0.3f}, 2), 3000, 2));
}

TEST(SdfTrace, TwoSpheresAgreeWithBvh) {
    lumina::test::Mesh mesh = lumina::test::makeIcosphere({-0.7f, 0, 0}, 0.5f, 3);
    mesh.append(lumina::test::makeIcosphere({0.7f, 0.2f, 0}, 0.4f, 3));
    expectAgreement(compare(mesh, 3000, 3));
}

TEST(SdfTrace, MissesTheVolumeAndStartsInside) {
    const lumina::test::Mesh mesh = lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 2);
    SdfSettings settings;
    settings.resolution = 16;
    const MeshSdf sdf = buildMeshSdf(mesh.positions, mesh.indices, settings);
    const SdfAtlas atlas = packSdfs(std::span<const MeshSdf>(&sdf, 1));
    EXPECT_FALSE(traceSdf(atlas, 0, {5, 5, 5}, glm::normalize(glm::vec3(1, 1, 1))).hit);
    EXPECT_FALSE(traceSdf(atlas, 0, {0, 3, 0}, {1, 0, 0}).hit); // axis-parallel, passing above the box
    const SdfTraceResult inside = traceSdf(atlas, 0, {0, 0, 0}, {1, 0, 0});
    EXPECT_TRUE(inside.hit);
    EXPECT_EQ(inside.t, 0.0f);
    const SdfTraceResult shortRay = traceSdf(atlas, 0, {-3, 0, 0}, {1, 0, 0}, 1.5f);
    EXPECT_FALSE(shortRay.hit); // the surface is at t = 2
    const SdfTraceResult longRay = traceSdf(atlas, 0, {-3, 0, 0}, {1, 0, 0}, 3.0f);
    EXPECT_TRUE(longRay.hit);
    EXPECT_NEAR(longRay.t, 2.0f, sdf.voxelSize);
}

} // namespace
} // namespace lumina::sdf
