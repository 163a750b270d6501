#pragma once
// A BVH over the world boxes of a scene's SDF instances, for the near-field tracer
// (shaders/common/sdf_near_field.hlsli) to find the instances a ray can reach.
//
// Same node layout as the triangle BVH (shaders/common/bvh_shared.h): depth-first, an
// interior node's first child follows it and `index` names the second; a leaf's `index`
// is its first entry in `instances` and `count` the number of entries. Built by median
// splits along the widest axis of the box centres: instance counts are small (thousands)
// and the tree is rebuilt whenever an instance moves, so build speed matters more than SAH
// quality; median splits also bound the depth by ceil(log2(n / maxLeafSize)) + 1.
#include "gi/bvh/bvh.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lumina::sdf {

struct InstanceBvh {
    std::vector<gpu::BvhNode> nodes; // empty when there are no instances
    std::vector<uint32_t> instances; // instance indices, grouped by leaf
    uint32_t depth = 0;              // levels; 1 for a single leaf
};

InstanceBvh buildInstanceBvh(std::span<const bvh::Aabb> boxes, uint32_t maxLeafSize = 2);

// The instances whose box (boxes[i], as given to the build) the segment origin + t * direction,
// t in [tMin, tMax], overlaps, in the order the GPU traversal visits them (CPU twin, for tests).
std::vector<uint32_t> instancesAlongRay(const InstanceBvh& bvh, std::span<const bvh::Aabb> boxes,
                                        const glm::vec3& origin, const glm::vec3& direction, float tMin,
                                        float tMax);

} // namespace lumina::sdf
