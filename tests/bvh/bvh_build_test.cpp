#include "gi/bvh/bvh.h"
#include "tests/bvh/test_meshes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <stdexcept>

namespace lumina::bvh {
namespace {

// Walks the tree from the root and checks the depth-first layout: first child at i + 1,
// second child after the first's subtree, children inside their parent, leaf ranges
// covering every triangle exactly once, and leaf triangles inside their leaf's box.
void checkLayout(const Bvh& bvh, const BvhBuildSettings& settings, size_t triangleCount) {
    ASSERT_EQ(bvh.triangles.size(), triangleCount);
    if (triangleCount == 0) {
        EXPECT_TRUE(bvh.nodes.empty());
        return;
    }
    std::vector<int> referenced(triangleCount, 0);
    std::vector<int> visited(bvh.nodes.size(), 0);
    uint32_t maxDepth = 0;
    // (node, depth, subtree end in the node array is checked via the next sibling index)
    std::vector<std::pair<uint32_t, uint32_t>> stack = {{0u, 1u}};
    while (!stack.empty()) {
        auto [index, depth] = stack.back();
        stack.pop_back();
        ASSERT_LT(index, bvh.nodes.size());
        ++visited[index];
        maxDepth = std::max(maxDepth, depth);
        const gpu::BvhNode& node = bvh.nodes[index];
        const Aabb box = nodeBounds(node);
        if (isLeaf(node)) {
            EXPECT_LE(nodeCount(node), settings.maxLeafSize);
            for (uint32_t i = nodeIndex(node); i < nodeIndex(node) + nodeCount(node); ++i) {
                ASSERT_LT(i, triangleCount);
                ++referenced[i];
                const gpu::BvhTriangle& t = bvh.triangles[i];
                Aabb tb;
                tb.extend(glm::vec3(t.v0));
                tb.extend(glm::vec3(t.v1));
                tb.extend(glm::vec3(t.v2));
                EXPECT_TRUE(box.contains(tb)) << "leaf " << index << " triangle " << i;
            }
            continue;
        }
        const uint32_t left = index + 1, right = nodeIndex(node);
        ASSERT_GT(right, left) << "node " << index;
        ASSERT_LT(right, bvh.nodes.size());
        EXPECT_TRUE(box.contains(nodeBounds(bvh.nodes[left]))) << "node " << index;
        EXPECT_TRUE(box.contains(nodeBounds(bvh.nodes[right]))) << "node " << index;
        stack.push_back({right, depth + 1});
        stack.push_back({left, depth + 1});
    }
    for (size_t i = 0; i < triangleCount; ++i) {
        ASSERT_EQ(referenced[i], 1) << "triangle " << i;
    }
    for (size_t i = 0; i < visited.size(); ++i) {
        ASSERT_EQ(visited[i], 1) << "node " << i << " reached " << visited[i] << " times";
    }
    EXPECT_EQ(maxDepth, bvh.depth);
}

std::vector<uint32_t> sortedPrimIds(const Bvh& bvh) {
    std::vector<uint32_t> ids;
    for (const gpu::BvhTriangle& t : bvh.triangles) {
        ids.push_back(primId(t));
    }
    std::sort(ids.begin(), ids.end());
    return ids;
}

TEST(BvhBuild, LayoutInvariantsOnRandomAndStructuredMeshes) {
    test::Mesh structured = test::makeBox({-1, -1, -1}, {1, 1, 1}, 12);
    structured.append(test::makeIcosphere({3, 0, 0}, 1.0f, 3));
    structured.append(test::makeGrid({-5, -5}, {5, 5}, -2.0f, 30));
    const test::Mesh meshes[] = {test::makeRandomTriangles(5000, 1), structured};
    for (const test::Mesh& mesh : meshes) {
        for (uint32_t leaf : {1u, 4u, 8u}) {
            BvhBuildSettings settings;
            settings.maxLeafSize = leaf;
            const Bvh bvh = buildBvh(mesh.positions, mesh.indices, settings);
            checkLayout(bvh, settings, mesh.triangleCount());
            // Every primitive id survives the reordering once.
            const std::vector<uint32_t> ids = sortedPrimIds(bvh);
            for (uint32_t i = 0; i < ids.size(); ++i) {
                ASSERT_EQ(ids[i], i);
            }
        }
    }
}

TEST(BvhBuild, KeepsTheGivenPrimitiveIds) {
    std::vector<BuildTriangle> triangles;
    for (uint32_t i = 0; i < 100; ++i) {
        const float x = float(i);
        triangles.push_back({{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}, 1000 + 7 * i});
    }
    const Bvh bvh = buildBvh(triangles);
    for (const gpu::BvhTriangle& t : bvh.triangles) {
        const uint32_t id = primId(t);
        ASSERT_EQ((id - 1000) % 7, 0u);
        EXPECT_EQ(t.v0.x, float((id - 1000) / 7));
    }
}

TEST(BvhBuild, EmptySingleAndCoincidentInputs) {
    const Bvh empty = buildBvh(std::span<const BuildTriangle>{});
    EXPECT_TRUE(empty.nodes.empty());
    EXPECT_EQ(empty.depth, 0u);

    const std::vector<BuildTriangle> one = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 42}};
    const Bvh single = buildBvh(one);
    ASSERT_EQ(single.nodes.size(), 1u);
    EXPECT_TRUE(isLeaf(single.nodes[0]));
    EXPECT_EQ(single.depth, 1u);

    // 1000 identical triangles: no plane separates their centroids; the build halves ranges.
    const std::vector<BuildTriangle> same(1000, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 7});
    BvhBuildSettings settings;
    const Bvh stacked = buildBvh(same, settings);
    checkLayout(stacked, settings, same.size());
    EXPECT_LE(stacked.depth, 9u);
}

TEST(BvhBuild, RejectsBadInput) {
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<uint32_t> badIndex = {0, 1, 3};
    EXPECT_THROW(buildBvh(positions, badIndex), std::invalid_argument);
    const std::vector<uint32_t> badCount = {0, 1};
    EXPECT_THROW(buildBvh(positions, badCount), std::invalid_argument);
    const std::vector<glm::vec3> nan = {{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}};
    const std::vector<uint32_t> tri = {0, 1, 2};
    EXPECT_THROW(buildBvh(nan, tri), std::invalid_argument);
    BvhBuildSettings settings;
    settings.binCount = 1;
    EXPECT_THROW(buildBvh(positions, tri, settings), std::invalid_argument);
}

TEST(BvhBuild, ThreadCountDoesNotChangeTheTree) {
    const test::Mesh mesh = test::makeRandomTriangles(60000, 3);
    BvhBuildSettings one, four;
    one.threads = 1;
    four.threads = 4;
    const Bvh a = buildBvh(mesh.positions, mesh.indices, one);
    const Bvh b = buildBvh(mesh.positions, mesh.indices, four);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(gpu::BvhNode)));
    EXPECT_EQ(0, std::memcmp(a.triangles.data(), b.triangles.data(),
                             a.triangles.size() * sizeof(gpu::BvhTriangle)));
    checkLayout(b, four, mesh.triangleCount());
}

TEST(BvhBuild, SahSeparatesDistantClusters) {
    // Two clusters far apart along x: the root must split between them.
    test::Mesh mesh = test::makeIcosphere({-100, 0, 0}, 1.0f, 2);
    mesh.append(test::makeIcosphere({100, 0, 0}, 1.0f, 2));
    const Bvh bvh = buildBvh(mesh.positions, mesh.indices);
    ASSERT_FALSE(isLeaf(bvh.nodes[0]));
    const Aabb left = nodeBounds(bvh.nodes[1]);
    const Aabb right = nodeBounds(bvh.nodes[nodeIndex(bvh.nodes[0])]);
    EXPECT_LT(std::min(left.max.x, right.max.x), -98.0f);
    EXPECT_GT(std::max(left.min.x, right.min.x), 98.0f);
}

TEST(BvhBuild, SahCostIsSane) {
    const test::Mesh mesh = test::makeRandomTriangles(20000, 5, 50.0f, 0.5f);
    BvhBuildSettings settings;
    const Bvh bvh = buildBvh(mesh.positions, mesh.indices, settings);
    const double cost = sahCost(bvh, settings);
    const double allInOneLeaf = settings.intersectionCost * double(mesh.triangleCount());
    // Small scattered triangles: a good tree costs a few dozen tests, not thousands.
    EXPECT_LT(cost, 0.005 * allInOneLeaf);
    EXPECT_GT(cost, settings.traversalCost); // at least the root

    // More bins never make a much worse tree, and the SAH build beats leaves of size 1 forced
    // everywhere when intersection is cheap relative to traversal.
    BvhBuildSettings coarse = settings;
    coarse.binCount = 4;
    EXPECT_LE(cost, 1.05 * sahCost(buildBvh(mesh.positions, mesh.indices, coarse), settings));
    BvhBuildSettings tiny = settings;
    tiny.maxLeafSize = 1;
    EXPECT_LE(cost, sahCost(buildBvh(mesh.positions, mesh.indices, tiny), settings));
}

} // namespace
} // namespace lumina::bvh
