#pragma once
// CPU queries on a Bvh: closest hit, any hit (both with the watertight test of
// shaders/common/ray_triangle.hlsli, the code the GPU runs) and the closest point on the
// triangles to a point (exact unsigned distance, for SDF generation).
#include "gi/bvh/bvh.h"

#include <cstdint>
#include <limits>

namespace lumina::bvh {

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, 1.0f}; // need not be normalised; t is in its units
    float tMin = 0.0f;
    float tMax = std::numeric_limits<float>::infinity();
};

inline constexpr uint32_t kNoHit = LUMINA_BVH_NO_HIT;

struct RayHit {
    float t = std::numeric_limits<float>::infinity();
    glm::vec2 barycentrics{0.0f}; // weights of v1 and v2
    uint32_t primId = kNoHit;
    uint32_t triangle = kNoHit; // index into Bvh::triangles
    bool hit() const { return primId != kNoHit; }
};

// Nearest hit with tMin < t <= tMax; a miss leaves primId == kNoHit.
RayHit intersectClosest(const Bvh& bvh, const Ray& ray);
// Whether anything is hit with tMin < t <= tMax (stops at the first hit found).
bool intersectAny(const Bvh& bvh, const Ray& ray);

struct ClosestPoint {
    glm::vec3 point{0.0f};
    float distanceSquared = std::numeric_limits<float>::infinity();
    glm::vec2 barycentrics{0.0f}; // weights of v1 and v2
    uint32_t primId = kNoHit;
    uint32_t triangle = kNoHit; // index into Bvh::triangles
    bool found() const { return triangle != kNoHit; }
};

// The point of the triangles nearest to p, searched within sqrt(maxDistanceSquared);
// found() is false when no triangle lies that close. A good bound (e.g. a neighbour's
// distance plus the step between them) prunes most of the tree.
ClosestPoint closestPoint(const Bvh& bvh, const glm::vec3& p,
                          float maxDistanceSquared = std::numeric_limits<float>::infinity());

// Closest point on one triangle (Ericson, Real-Time Collision Detection, 5.1.5).
// Returns the point and writes the weights of b and c.
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c, glm::vec2& barycentrics);

} // namespace lumina::bvh
