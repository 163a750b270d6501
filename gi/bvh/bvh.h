#pragma once
// A triangle BVH for the CPU and the GPU: binned-SAH build over world-space triangles,
// flattened depth-first into the 32-byte nodes of shaders/common/bvh_shared.h, with the
// triangles reordered so that every leaf names one contiguous range.
//
// Used by the path tracer (closest/any hit, CPU here and shaders/common/bvh_traversal.hlsli
// on the GPU) and by the SDF builder (closest point on the mesh, ray-vote signs).
#include "shaders/common/bvh_shared.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <span>
#include <vector>

namespace lumina::bvh {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};

    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    glm::vec3 size() const { return max - min; }
    glm::vec3 centre() const { return 0.5f * (min + max); }
    // Half the surface area is enough for SAH ratios; empty boxes have none.
    float halfArea() const {
        if (empty()) {
            return 0.0f;
        }
        const glm::vec3 d = size();
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
    bool contains(const Aabb& b) const {
        return glm::all(glm::lessThanEqual(min, b.min)) && glm::all(glm::greaterThanEqual(max, b.max));
    }
};

// One world-space triangle; primId is handed back by every query (e.g. instance and
// triangle packed by the caller).
struct BuildTriangle {
    glm::vec3 v0, v1, v2;
    uint32_t primId = 0;
};

struct BvhBuildSettings {
    uint32_t binCount = 32;        // SAH bins per axis (2..64)
    uint32_t maxLeafSize = 8;      // leaves never hold more triangles
    float traversalCost = 1.0f;    // SAH cost of visiting a node, relative to...
    float intersectionCost = 1.0f; // ...one ray/triangle test
    uint32_t threads = 0;          // 0: std::thread::hardware_concurrency()
};

struct Bvh {
    std::vector<gpu::BvhNode> nodes;         // depth-first, root at 0 (empty for no triangles)
    std::vector<gpu::BvhTriangle> triangles; // reordered by leaf
    Aabb bounds;
    uint32_t depth = 0; // levels, 1 for a single leaf (the GPU stack needs depth - 1 entries)
};

// Throws std::invalid_argument for bad settings or indices (naming the offending value).
Bvh buildBvh(std::span<const BuildTriangle> triangles, const BvhBuildSettings& settings = {});
// Convenience for one indexed mesh: primId = triangle number (index / 3).
Bvh buildBvh(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
             const BvhBuildSettings& settings = {});

// Node fields, decoded from the GPU layout.
inline bool isLeaf(const gpu::BvhNode& node) {
    return gpu::asuint(node.maxAndCount.w) != 0;
}
inline uint32_t nodeIndex(const gpu::BvhNode& node) {
    return gpu::asuint(node.minAndIndex.w);
}
inline uint32_t nodeCount(const gpu::BvhNode& node) {
    return gpu::asuint(node.maxAndCount.w);
}
inline Aabb nodeBounds(const gpu::BvhNode& node) {
    return {glm::vec3(node.minAndIndex), glm::vec3(node.maxAndCount)};
}
inline uint32_t primId(const gpu::BvhTriangle& tri) {
    return gpu::asuint(tri.v0.w);
}

// The SAH cost of the finished tree under the given costs, normalised by the root's area:
// sum over interior nodes of traversalCost * A(n)/A(root) plus, over leaves,
// intersectionCost * count * A(n)/A(root).
double sahCost(const Bvh& bvh, const BvhBuildSettings& settings = {});

} // namespace lumina::bvh
