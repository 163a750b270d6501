#include "gi/bvh/bvh_query.h"
#include "tests/bvh/test_meshes.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <random>

namespace lumina::bvh {
namespace {

// Rays aimed at shared vertices and at points of shared edges of closed meshes, from inside
// and from outside: every one must hit. Slipping through between two triangles is what a
// non-watertight test does at such points. The direction (target - origin) is rounded, so a
// ray passes within an ulp or so of its target: from outside, only targets whose incident
// triangles all face the ray count (near the silhouette, passing beside the target is a true
// miss); from a point inside a closed mesh, every ray must hit.
struct Target {
    glm::vec3 point;
    std::vector<uint32_t> triangles; // incident triangles
};

std::vector<Target> edgeAndVertexTargets(const test::Mesh& mesh, std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Target> targets(mesh.positions.size());
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> edges;
    for (uint32_t t = 0; t < mesh.triangleCount(); ++t) {
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = mesh.indices[3 * t + e], b = mesh.indices[3 * t + (e + 1) % 3];
            targets[a].point = mesh.positions[a];
            targets[a].triangles.push_back(t);
            edges[std::minmax(a, b)].push_back(t);
        }
    }
    for (const auto& [edge, tris] : edges) {
        const glm::vec3 a = mesh.positions[edge.first], b = mesh.positions[edge.second];
        targets.push_back({0.5f * (a + b), tris});            // edge midpoint
        targets.push_back({glm::mix(a, b, unit(rng)), tris}); // anywhere on the edge
    }
    return targets;
}

bool facesTheRay(const test::Mesh& mesh, const Target& target, const glm::vec3& direction) {
    for (uint32_t t : target.triangles) {
        const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                        c = mesh.positions[mesh.indices[3 * t + 2]];
        const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        if (glm::dot(n, glm::normalize(direction)) > -0.05f) {
            return false;
        }
    }
    return true;
}

void expectNoLeaks(const test::Mesh& mesh, glm::vec3 inside, uint32_t seed) {
    const Bvh bvh = buildBvh(mesh.positions, mesh.indices);
    std::mt19937 rng(seed);
    const float farAway = 4.0f * glm::length(bvh.bounds.size());
    uint32_t misses = 0, rays = 0;
    for (const Target& target : edgeAndVertexTargets(mesh, rng)) {
        Ray fromInside;
        fromInside.origin = inside;
        fromInside.direction = target.point - inside;
        misses += !intersectAny(bvh, fromInside);
        misses += !intersectClosest(bvh, fromInside).hit();
        rays += 2;

        Ray fromOutside;
        fromOutside.origin = inside + farAway * test::randomUnitVector(rng);
        fromOutside.direction = target.point - fromOutside.origin;
        if (facesTheRay(mesh, target, fromOutside.direction)) {
            misses += !intersectClosest(bvh, fromOutside).hit();
            ++rays;
        }
    }
    EXPECT_EQ(misses, 0u) << "of " << rays << " rays";
    EXPECT_GT(rays, 4 * mesh.positions.size());
}

TEST(BvhWatertight, IcosphereEdgesAndVertices) {
    expectNoLeaks(test::makeIcosphere({0.3f, -0.2f, 0.1f}, 2.0f, 3), {0.3f, -0.2f, 0.1f}, 31);
}

TEST(BvhWatertight, SubdividedBoxEdgesAndVertices) {
    expectNoLeaks(test::makeBox({-1.1f, -0.7f, -1.3f}, {0.9f, 1.7f, 0.3f}, 7), {0.0f, 0.1f, -0.2f}, 32);
}

TEST(BvhWatertight, AxisAlignedRaysThroughGridVertices) {
    // A box with lattice vertices exactly on the rays' paths: axis-aligned rays through
    // vertices and edges, where the projected triangles meet at exactly zero edge functions.
    const test::Mesh mesh = test::makeBox({-2, -2, -2}, {2, 2, 2}, 4);
    const Bvh bvh = buildBvh(mesh.positions, mesh.indices);
    uint32_t misses = 0, rays = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (int i = -4; i <= 4; ++i) {
            for (int j = -4; j <= 4; ++j) {
                for (float sign : {-1.0f, 1.0f}) {
                    Ray ray;
                    ray.origin = glm::vec3(0.0f);
                    ray.origin[(axis + 1) % 3] =
                        0.5f * float(i) * 0.999999f; // inside the face, or on its rim
                    ray.origin[(axis + 2) % 3] = 0.5f * float(j);
                    ray.origin[axis] = -10.0f * sign;
                    ray.direction = glm::vec3(0.0f);
                    ray.direction[axis] = sign;
                    ++rays;
                    misses += !intersectClosest(bvh, ray).hit();
                }
            }
        }
    }
    EXPECT_EQ(misses, 0u) << "of " << rays;
}

} // namespace
} // namespace lumina::bvh
