// The GPU BVH traversal (shaders/common/bvh_traversal.hlsli, through the test kernel
// shaders/bvh/bvh_raycast_test.hlsl) against the CPU traversal on the same tree and rays.
#include "gi/bvh/bvh_query.h"
#include "shaders/bvh/bvh_test_shared.h"
#include "shaders/common/constants_shared.h"
#include "tests/bvh/test_meshes.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <random>

namespace lumina::test {
namespace {

using BvhGpuTest = GpuTest;

constexpr uint32_t kGroupSize = LUMINA_LINEAR_GROUP_SIZE; // numthreads of bvh_raycast_test

std::vector<gpu::BvhRay> makeRays(uint32_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-8.0f, 8.0f);
    std::vector<gpu::BvhRay> rays(count);
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3 origin(pos(rng), pos(rng), pos(rng));
        glm::vec3 direction =
            (i % 2 == 0) ? randomUnitVector(rng) : glm::vec3(pos(rng), pos(rng), pos(rng)) * 0.3f - origin;
        if (i % 7 == 0) {
            direction = glm::vec3(0.0f);
            direction[i % 3] = (i % 2) ? 1.0f : -1.0f;
        }
        const float tMin = (i % 5 == 0) ? 0.5f : 0.0f;
        const float tMax = (i % 5 == 0) ? 8.0f : 1e30f;
        rays[i] = {glm::vec4(origin, tMin), glm::vec4(direction, tMax)};
    }
    return rays;
}

TEST_P(BvhGpuTest, TraversalMatchesTheCpu) {
    Mesh mesh = makeBox({-2, -2, -2}, {2, 2, 2}, 6);
    mesh.append(makeIcosphere({0, 0, 0}, 1.5f, 3));
    mesh.append(makeRandomTriangles(2000, 7, 6.0f, 0.8f));
    const bvh::Bvh bvh = bvh::buildBvh(mesh.positions, mesh.indices);
    ASSERT_LE(bvh.depth, 65u) << "deeper than the GPU stack";
    constexpr uint32_t kRays = 4096;
    const std::vector<gpu::BvhRay> rays = makeRays(kRays, 11);

    auto structured = [&](const void* data, size_t count, size_t stride, const char* name) {
        return rhi::createBufferWithData(device(),
                                         {.size = count * stride,
                                          .structStride = uint32_t(stride),
                                          .usage = rhi::BufferUsage::Structured,
                                          .debugName = name},
                                         data, count * stride);
    };
    rhi::BufferHandle nodes =
        structured(bvh.nodes.data(), bvh.nodes.size(), sizeof(gpu::BvhNode), "bvh nodes");
    rhi::BufferHandle triangles =
        structured(bvh.triangles.data(), bvh.triangles.size(), sizeof(gpu::BvhTriangle), "bvh triangles");
    rhi::BufferHandle rayBuffer = structured(rays.data(), rays.size(), sizeof(gpu::BvhRay), "bvh rays");
    const ComputeKernel kernel = loadComputeKernel("bvh/bvh_raycast_test",
                                                   {{rhi::BindingType::BufferSRV, 0},
                                                    {rhi::BindingType::BufferSRV, 1},
                                                    {rhi::BindingType::BufferSRV, 2},
                                                    {rhi::BindingType::BufferUAV, 0}},
                                                   sizeof(gpu::BvhRaycastConstants));

    for (uint32_t anyHit : {0u, 1u}) {
        SCOPED_TRACE(anyHit ? "any hit" : "closest hit");
        rhi::BufferHandle hits =
            device().createBuffer({.size = kRays * sizeof(gpu::BvhRayHit),
                                   .structStride = sizeof(gpu::BvhRayHit),
                                   .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                   .debugName = "bvh hits"});
        rhi::CommandListHandle list = device().createCommandList();
        list->begin();
        list->setComputeState({.pipeline = kernel.pipeline,
                               .bindings = {{kernel.layout,
                                             {rhi::BindingSetItem::structuredBuffer(0, nodes),
                                              rhi::BindingSetItem::structuredBuffer(1, triangles),
                                              rhi::BindingSetItem::structuredBuffer(2, rayBuffer),
                                              rhi::BindingSetItem::rwStructuredBuffer(0, hits)}}}});
        list->pushConstants(gpu::BvhRaycastConstants{kRays, anyHit, 0, 0});
        list->dispatch((kRays + kGroupSize - 1) / kGroupSize);
        list->end();
        submitAndWait(*list);

        const std::vector<gpu::BvhRayHit> gpuHits = readBack<gpu::BvhRayHit>(*hits);
        ASSERT_EQ(gpuHits.size(), kRays);
        // The CPU breaks exact-zero edge functions in double precision, the GPU does not:
        // allow a handful of rays through shared edges to name the other triangle.
        uint32_t hitMismatches = 0, primMismatches = 0, hitCount = 0;
        for (uint32_t i = 0; i < kRays; ++i) {
            bvh::Ray ray;
            ray.origin = glm::vec3(rays[i].originAndTMin);
            ray.tMin = rays[i].originAndTMin.w;
            ray.direction = glm::vec3(rays[i].directionAndTMax);
            ray.tMax = rays[i].directionAndTMax.w;
            const uint32_t gpuPrim = gpu::asuint(gpuHits[i].tuvAndPrim.w);
            if (anyHit) {
                hitMismatches += bvh::intersectAny(bvh, ray) != (gpuPrim != bvh::kNoHit);
                continue;
            }
            const bvh::RayHit cpu = bvh::intersectClosest(bvh, ray);
            if (cpu.hit() != (gpuPrim != bvh::kNoHit)) {
                ++hitMismatches;
                continue;
            }
            if (!cpu.hit()) {
                EXPECT_EQ(gpuHits[i].tuvAndPrim.x, ray.tMax) << "ray " << i;
                continue;
            }
            ++hitCount;
            EXPECT_NEAR(gpuHits[i].tuvAndPrim.x, cpu.t, 1e-5f * cpu.t) << "ray " << i;
            if (gpuPrim != cpu.primId) {
                ++primMismatches;
            } else {
                EXPECT_NEAR(gpuHits[i].tuvAndPrim.y, cpu.barycentrics.x, 1e-4f) << "ray " << i;
                EXPECT_NEAR(gpuHits[i].tuvAndPrim.z, cpu.barycentrics.y, 1e-4f) << "ray " << i;
            }
        }
        EXPECT_LE(hitMismatches, kRays / 1000);
        EXPECT_LE(primMismatches, kRays / 1000);
        if (!anyHit) {
            EXPECT_GT(hitCount, kRays / 4);
        }
    }
}

LUMINA_INSTANTIATE_GPU_TEST(BvhGpuTest);

} // namespace
} // namespace lumina::test
