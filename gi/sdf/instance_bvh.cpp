#include "gi/sdf/instance_bvh.h"

#include "shaders/common/ray_box.hlsli"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace lumina::sdf {
namespace {

struct Builder {
    std::span<const bvh::Aabb> boxes;
    uint32_t maxLeafSize;
    InstanceBvh& out;

    // Builds the subtree over out.instances[first, first + count); returns its depth.
    uint32_t build(uint32_t first, uint32_t count) {
        const uint32_t node = uint32_t(out.nodes.size());
        out.nodes.emplace_back();
        bvh::Aabb bounds, centres;
        for (uint32_t i = first; i < first + count; ++i) {
            bounds.extend(boxes[out.instances[i]]);
            centres.extend(boxes[out.instances[i]].centre());
        }
        const auto write = [&](uint32_t index, uint32_t leafCount) {
            out.nodes[node].minAndIndex = glm::vec4(bounds.min, gpu::asfloat(index));
            out.nodes[node].maxAndCount = glm::vec4(bounds.max, gpu::asfloat(leafCount));
        };
        if (count <= maxLeafSize) {
            write(first, count);
            return 1;
        }
        const glm::vec3 extent = centres.size();
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const uint32_t half = count / 2;
        auto begin = out.instances.begin() + first;
        // Ties broken by index, so that the tree does not depend on the library's nth_element.
        std::nth_element(begin, begin + half, begin + count, [&](uint32_t a, uint32_t b) {
            const float ca = boxes[a].centre()[axis], cb = boxes[b].centre()[axis];
            return ca < cb || (ca == cb && a < b);
        });
        const uint32_t leftDepth = build(first, half);
        const uint32_t right = uint32_t(out.nodes.size());
        const uint32_t rightDepth = build(first + half, count - half);
        write(right, 0);
        return 1 + std::max(leftDepth, rightDepth);
    }
};

} // namespace

InstanceBvh buildInstanceBvh(std::span<const bvh::Aabb> boxes, uint32_t maxLeafSize) {
    if (maxLeafSize == 0) {
        throw std::invalid_argument("buildInstanceBvh: maxLeafSize must be at least 1");
    }
    InstanceBvh bvh;
    if (boxes.empty()) {
        return bvh;
    }
    for (size_t i = 0; i < boxes.size(); ++i) {
        if (boxes[i].empty()) {
            throw std::invalid_argument("buildInstanceBvh: instance " + std::to_string(i) +
                                        " has an empty box");
        }
    }
    bvh.instances.resize(boxes.size());
    std::iota(bvh.instances.begin(), bvh.instances.end(), 0u);
    bvh.nodes.reserve(2 * boxes.size());
    Builder builder{boxes, maxLeafSize, bvh};
    bvh.depth = builder.build(0, uint32_t(boxes.size()));
    return bvh;
}

std::vector<uint32_t> instancesAlongRay(const InstanceBvh& bvh, std::span<const bvh::Aabb> boxes,
                                        const glm::vec3& origin, const glm::vec3& direction, float tMin,
                                        float tMax) {
    std::vector<uint32_t> found;
    if (bvh.nodes.empty()) {
        return found;
    }
    const glm::vec3 invDir = gpu::safeReciprocal3(direction);
    std::vector<uint32_t> stack = {0};
    while (!stack.empty()) {
        const uint32_t node = stack.back();
        stack.pop_back();
        const gpu::BvhNode& n = bvh.nodes[node];
        if (gpu::intersectBox(origin, invDir, glm::vec3(n.minAndIndex), glm::vec3(n.maxAndCount), tMin,
                              tMax) < 0.0f) {
            continue;
        }
        if (bvh::isLeaf(n)) {
            for (uint32_t i = 0; i < bvh::nodeCount(n); ++i) {
                const uint32_t instance = bvh.instances[bvh::nodeIndex(n) + i];
                if (gpu::intersectBox(origin, invDir, boxes[instance].min, boxes[instance].max, tMin, tMax) >=
                    0.0f) {
                    found.push_back(instance);
                }
            }
        } else {
            stack.push_back(bvh::nodeIndex(n));
            stack.push_back(node + 1);
        }
    }
    return found;
}

} // namespace lumina::sdf
