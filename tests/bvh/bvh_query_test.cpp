#include "gi/bvh/bvh_query.h"
#include "shaders/common/ray_triangle.hlsli"
#include "tests/bvh/test_meshes.h"

#include <gtest/gtest.h>
#include <random>

namespace lumina::bvh {
namespace {

// The same watertight test over every triangle, no tree.
RayHit bruteForceClosest(const Bvh& bvh, const Ray& ray) {
    RayHit hit;
    const gpu::WatertightRay wray = gpu::makeWatertightRay(ray.origin, ray.direction);
    float tMax = ray.tMax;
    for (uint32_t i = 0; i < bvh.triangles.size(); ++i) {
        const gpu::BvhTriangle& tri = bvh.triangles[i];
        float t;
        glm::vec2 bary;
        if (gpu::intersectTriangleWatertight(wray, glm::vec3(tri.v0), glm::vec3(tri.v1), glm::vec3(tri.v2),
                                             ray.tMin, tMax, t, bary)) {
            tMax = t;
            hit = {t, bary, primId(tri), i};
        }
    }
    return hit;
}

std::vector<Ray> randomRays(uint32_t count, uint32_t seed, float extent) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-extent, extent);
    std::vector<Ray> rays;
    for (uint32_t i = 0; i < count; ++i) {
        Ray ray;
        ray.origin = {pos(rng), pos(rng), pos(rng)};
        if (i % 2 == 0) {
            ray.direction = test::randomUnitVector(rng);
        } else { // aimed at a point inside the volume, unnormalised, so that most rays hit
            ray.direction = glm::vec3(pos(rng), pos(rng), pos(rng)) * 0.3f - ray.origin;
        }
        if (i % 7 == 0) { // axis-parallel directions exercise the zero-reciprocal path
            ray.direction = glm::vec3(0.0f);
            ray.direction[i % 3] = (i % 2) ? 1.0f : -1.0f;
        }
        if (i % 5 == 0) {
            ray.tMin = 0.5f;
            ray.tMax = 8.0f;
        }
        rays.push_back(ray);
    }
    return rays;
}

void expectSameAsBruteForce(const test::Mesh& mesh, uint32_t rayCount, float extent, uint32_t seed) {
    const Bvh bvh = buildBvh(mesh.positions, mesh.indices);
    uint32_t hits = 0;
    for (const Ray& ray : randomRays(rayCount, seed, extent)) {
        const RayHit expected = bruteForceClosest(bvh, ray);
        const RayHit actual = intersectClosest(bvh, ray);
        ASSERT_EQ(actual.hit(), expected.hit())
            << "ray from " << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z;
        EXPECT_EQ(intersectAny(bvh, ray), expected.hit());
        if (expected.hit()) {
            ++hits;
            EXPECT_NEAR(actual.t, expected.t, 1e-5f * expected.t);
            const gpu::BvhTriangle& tri = bvh.triangles[actual.triangle];
            EXPECT_EQ(primId(tri), actual.primId);
            // The reported barycentrics reproduce the hit point.
            const glm::vec3 p = ray.origin + actual.t * ray.direction;
            const glm::vec3 q = glm::vec3(tri.v0) * (1.0f - actual.barycentrics.x - actual.barycentrics.y) +
                                glm::vec3(tri.v1) * actual.barycentrics.x +
                                glm::vec3(tri.v2) * actual.barycentrics.y;
            EXPECT_LT(glm::length(p - q), 1e-3f * (1.0f + glm::length(p)));
        }
    }
    EXPECT_GT(hits, rayCount / 10) << "too few hits to mean anything";
}

TEST(BvhQuery, ClosestHitMatchesBruteForceOnRandomTriangles) {
    expectSameAsBruteForce(test::makeRandomTriangles(3000, 11, 10.0f, 1.5f), 4000, 14.0f, 12);
}

TEST(BvhQuery, ClosestHitMatchesBruteForceOnStructuredMeshes) {
    test::Mesh mesh = test::makeBox({-2, -2, -2}, {2, 2, 2}, 10);
    mesh.append(test::makeIcosphere({0, 0, 0}, 1.5f, 3));
    mesh.append(test::makeGrid({-6, -6}, {6, 6}, -3.0f, 24));
    mesh.append(test::makeGrid({-6, -6}, {6, 6}, 2.0f, 7)); // coplanar with the box's top face
    expectSameAsBruteForce(mesh, 4000, 8.0f, 13);
}

TEST(BvhQuery, EmptyBvhMissesEverything) {
    const Bvh bvh;
    EXPECT_FALSE(intersectClosest(bvh, Ray{}).hit());
    EXPECT_FALSE(intersectAny(bvh, Ray{}));
    EXPECT_FALSE(closestPoint(bvh, glm::vec3(0.0f)).found());
}

TEST(BvhQuery, ClosestPointMatchesBruteForce) {
    test::Mesh mesh = test::makeRandomTriangles(2000, 21, 5.0f, 1.0f);
    mesh.append(test::makeIcosphere({0, 0, 0}, 3.0f, 3));
    // Degenerate triangles must not produce NaNs.
    mesh.positions.insert(mesh.positions.end(),
                          {{9, 9, 9}, {9, 9, 9}, {9, 9, 9}, {8, 0, 0}, {9, 0, 0}, {10, 0, 0}});
    const uint32_t base = uint32_t(mesh.positions.size()) - 6;
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base + 3, base + 4, base + 5});
    const Bvh bvh = buildBvh(mesh.positions, mesh.indices);

    std::mt19937 rng(22);
    std::uniform_real_distribution<float> pos(-12.0f, 12.0f);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 p(pos(rng), pos(rng), pos(rng));
        float expected = std::numeric_limits<float>::infinity();
        for (const gpu::BvhTriangle& t : bvh.triangles) {
            glm::vec2 bary;
            const glm::vec3 q =
                closestPointOnTriangle(p, glm::vec3(t.v0), glm::vec3(t.v1), glm::vec3(t.v2), bary);
            expected = std::min(expected, glm::dot(q - p, q - p));
        }
        const ClosestPoint cp = closestPoint(bvh, p);
        ASSERT_TRUE(cp.found());
        EXPECT_FLOAT_EQ(cp.distanceSquared, expected);
        EXPECT_FLOAT_EQ(glm::dot(cp.point - p, cp.point - p), cp.distanceSquared);
        // The barycentrics name the same point.
        const gpu::BvhTriangle& t = bvh.triangles[cp.triangle];
        const glm::vec3 q = glm::vec3(t.v0) * (1.0f - cp.barycentrics.x - cp.barycentrics.y) +
                            glm::vec3(t.v1) * cp.barycentrics.x + glm::vec3(t.v2) * cp.barycentrics.y;
        EXPECT_LT(glm::length(q - cp.point), 1e-4f * (1.0f + glm::length(q)));
        // A bound just above the answer finds the same point; one below finds nothing.
        EXPECT_FLOAT_EQ(closestPoint(bvh, p, expected * 1.001f + 1e-12f).distanceSquared, expected);
        if (expected > 1e-6f) {
            EXPECT_FALSE(closestPoint(bvh, p, expected * 0.999f).found());
        }
    }
}

TEST(BvhQuery, ClosestPointOnTriangleRegions) {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    glm::vec2 bary;
    EXPECT_EQ(closestPointOnTriangle({-1, -1, 0}, a, b, c, bary), a);
    EXPECT_EQ(closestPointOnTriangle({2, -0.5f, 0}, a, b, c, bary), b);
    EXPECT_EQ(closestPointOnTriangle({-0.5f, 2, 1}, a, b, c, bary), c);
    EXPECT_EQ(closestPointOnTriangle({0.5f, -1, 0}, a, b, c, bary), glm::vec3(0.5f, 0, 0));
    EXPECT_EQ(closestPointOnTriangle({0.25f, 0.25f, 3}, a, b, c, bary), glm::vec3(0.25f, 0.25f, 0));
    EXPECT_FLOAT_EQ(bary.x, 0.25f);
    EXPECT_FLOAT_EQ(bary.y, 0.25f);
    const glm::vec3 onHypotenuse = closestPointOnTriangle({1, 1, 0}, a, b, c, bary);
    EXPECT_FLOAT_EQ(onHypotenuse.x, 0.5f);
    EXPECT_FLOAT_EQ(onHypotenuse.y, 0.5f);
}

} // namespace
} // namespace lumina::bvh
