#include "gi/sdf/instance_bvh.h"
#include "shaders/common/ray_box.hlsli"

#include <algorithm>
#include <gtest/gtest.h>
#include <random>

namespace lumina::sdf {
namespace {

std::vector<bvh::Aabb> randomBoxes(uint32_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> position(-50.0f, 50.0f), size(0.1f, 5.0f);
    std::vector<bvh::Aabb> boxes(count);
    for (bvh::Aabb& box : boxes) {
        box.min = {position(rng), position(rng), position(rng)};
        box.max = box.min + glm::vec3(size(rng), size(rng), size(rng));
    }
    return boxes;
}

TEST(InstanceBvh, EveryInstanceOnceAndNodesContainTheirChildren) {
    for (uint32_t count : {1u, 2u, 3u, 7u, 100u, 1025u}) {
        const std::vector<bvh::Aabb> boxes = randomBoxes(count, count);
        const InstanceBvh tree = buildInstanceBvh(boxes);
        std::vector<uint32_t> sorted = tree.instances;
        std::sort(sorted.begin(), sorted.end());
        ASSERT_EQ(sorted.size(), count);
        for (uint32_t i = 0; i < count; ++i) {
            EXPECT_EQ(sorted[i], i);
        }
        uint32_t leaves = 0;
        for (size_t n = 0; n < tree.nodes.size(); ++n) {
            const bvh::Aabb box = bvh::nodeBounds(tree.nodes[n]);
            if (bvh::isLeaf(tree.nodes[n])) {
                ++leaves;
                EXPECT_LE(bvh::nodeCount(tree.nodes[n]), 2u);
                for (uint32_t k = 0; k < bvh::nodeCount(tree.nodes[n]); ++k) {
                    EXPECT_TRUE(box.contains(boxes[tree.instances[bvh::nodeIndex(tree.nodes[n]) + k]]));
                }
            } else {
                EXPECT_TRUE(box.contains(bvh::nodeBounds(tree.nodes[n + 1])));
                EXPECT_TRUE(box.contains(bvh::nodeBounds(tree.nodes[bvh::nodeIndex(tree.nodes[n])])));
            }
        }
        EXPECT_EQ(tree.nodes.size(), 2 * leaves - 1);
        // Median splits: depth at most ceil(log2(count / 2)) + 1.
        EXPECT_LE(tree.depth, uint32_t(std::ceil(std::log2(std::max(1.0, count / 2.0)))) + 1) << count;
    }
    EXPECT_TRUE(buildInstanceBvh({}).nodes.empty());
}

TEST(InstanceBvh, RayQueriesFindExactlyTheOverlappedBoxes) {
    const std::vector<bvh::Aabb> boxes = randomBoxes(300, 5);
    const InstanceBvh tree = buildInstanceBvh(boxes);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-60.0f, 60.0f);
    for (int r = 0; r < 200; ++r) {
        const glm::vec3 origin(u(rng), u(rng), u(rng));
        const glm::vec3 direction = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
        const float tMax = r % 2 == 0 ? 1e30f : 40.0f;
        std::vector<uint32_t> found = instancesAlongRay(tree, boxes, origin, direction, 0.0f, tMax);
        std::sort(found.begin(), found.end());
        std::vector<uint32_t> expected;
        for (uint32_t i = 0; i < boxes.size(); ++i) {
            if (gpu::intersectBox(origin, gpu::safeReciprocal3(direction), boxes[i].min, boxes[i].max, 0.0f,
                                  tMax) >= 0.0f) {
                expected.push_back(i);
            }
        }
        EXPECT_EQ(found, expected) << "ray " << r;
    }
}

} // namespace
} // namespace lumina::sdf
