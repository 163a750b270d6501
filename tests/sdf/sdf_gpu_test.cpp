// GPU sampling and sphere tracing of the SDF atlas (shaders/common/sdf_sampling.hlsli,
// through shaders/sdf/sdf_trace_test.hlsl) against the CPU reference (sampleSdf, traceSdf).
// Hardware trilinear weights have 8 fractional bits, so values differ by up to a few
// thousandths of a voxel and a sphere trace may stop a step apart.
#include "gi/sdf/sdf_trace.h"
#include "shaders/common/constants_shared.h"
#include "shaders/sdf/sdf_test_shared.h"
#include "tests/bvh/test_meshes.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <random>

namespace lumina::test {
namespace {

using SdfGpuTest = GpuTest;

constexpr uint32_t kGroupSize = LUMINA_LINEAR_GROUP_SIZE; // numthreads of sdf_trace_test

TEST_P(SdfGpuTest, SphereTracingMatchesTheCpu) {
    // Two meshes in one atlas; the second (a box) is traced, so its atlas offset is non-zero.
    const Mesh sphere = makeIcosphere({0, 0, 0}, 1.0f, 3);
    const Mesh box = makeBox({-1.0f, -0.4f, -0.7f}, {0.8f, 0.6f, 0.3f}, 2);
    sdf::SdfSettings settings;
    settings.resolution = 32;
    const std::vector<sdf::MeshSdf> sdfs = {sdf::buildMeshSdf(sphere.positions, sphere.indices, settings),
                                            sdf::buildMeshSdf(box.positions, box.indices, settings)};
    const sdf::SdfAtlas atlas = sdf::packSdfs(sdfs); // R16F
    constexpr uint32_t kVolume = 1;
    const sdf::MeshSdf& traced = sdfs[kVolume];

    constexpr uint32_t kRays = 2048;
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const glm::vec3 centre = traced.meshBounds.centre();
    const float radius = 0.5f * glm::length(traced.meshBounds.size());
    std::vector<gpu::BvhRay> rays(kRays);
    for (gpu::BvhRay& ray : rays) {
        const glm::vec3 origin = centre + 1.5f * radius * randomUnitVector(rng);
        const glm::vec3 target = centre + 0.8f * radius * glm::vec3(u(rng), u(rng), u(rng));
        ray = {glm::vec4(origin, 0.0f), glm::vec4(glm::normalize(target - origin), 1e30f)};
    }

    rhi::TextureHandle atlasTexture = device().createTexture({.dimension = rhi::TextureDimension::Texture3D,
                                                              .format = rhi::Format::R16_FLOAT,
                                                              .width = atlas.dims.x,
                                                              .height = atlas.dims.y,
                                                              .depth = atlas.dims.z,
                                                              .debugName = "sdf atlas"});
    rhi::writeTexture(device(), *atlasTexture, {}, atlas.data());
    rhi::BufferHandle volumes =
        rhi::createBufferWithData(device(),
                                  {.size = atlas.volumes.size() * sizeof(gpu::SdfVolumeDesc),
                                   .structStride = sizeof(gpu::SdfVolumeDesc),
                                   .usage = rhi::BufferUsage::Structured,
                                   .debugName = "sdf volumes"},
                                  atlas.volumes.data(), atlas.volumes.size() * sizeof(gpu::SdfVolumeDesc));
    rhi::BufferHandle rayBuffer = rhi::createBufferWithData(device(),
                                                            {.size = kRays * sizeof(gpu::BvhRay),
                                                             .structStride = sizeof(gpu::BvhRay),
                                                             .usage = rhi::BufferUsage::Structured,
                                                             .debugName = "sdf rays"},
                                                            rays.data(), kRays * sizeof(gpu::BvhRay));
    rhi::BufferHandle hits =
        device().createBuffer({.size = kRays * sizeof(glm::vec4),
                               .structStride = sizeof(glm::vec4),
                               .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                               .debugName = "sdf hits"});
    rhi::SamplerHandle linearClamp = device().createSampler({.debugName = "linear clamp"});
    const ComputeKernel kernel = loadComputeKernel("sdf/sdf_trace_test",
                                                   {{rhi::BindingType::TextureSRV, 0},
                                                    {rhi::BindingType::BufferSRV, 1},
                                                    {rhi::BindingType::BufferSRV, 2},
                                                    {rhi::BindingType::Sampler, 0},
                                                    {rhi::BindingType::BufferUAV, 0}},
                                                   sizeof(gpu::SdfTraceTestConstants));

    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->setComputeState({.pipeline = kernel.pipeline,
                           .bindings = {{kernel.layout,
                                         {rhi::BindingSetItem::sampledTexture(0, atlasTexture),
                                          rhi::BindingSetItem::structuredBuffer(1, volumes),
                                          rhi::BindingSetItem::structuredBuffer(2, rayBuffer),
                                          rhi::BindingSetItem::samplerState(0, linearClamp),
                                          rhi::BindingSetItem::rwStructuredBuffer(0, hits)}}}});
    list->pushConstants(gpu::SdfTraceTestConstants{atlas.info().invAtlasDims, kRays, kVolume, 0, 0});
    list->dispatch((kRays + kGroupSize - 1) / kGroupSize);
    list->end();
    submitAndWait(*list);

    const std::vector<glm::vec4> gpuHits = readBack<glm::vec4>(*hits);
    ASSERT_EQ(gpuHits.size(), kRays);
    const float voxel = traced.voxelSize;
    uint32_t agree = 0, bothHit = 0, closeHits = 0;
    for (uint32_t i = 0; i < kRays; ++i) {
        const glm::vec3 origin(rays[i].originAndTMin), direction(rays[i].directionAndTMax);
        EXPECT_NEAR(gpuHits[i].w, sdf::sampleSdf(atlas, kVolume, origin), 0.02f * voxel) << "ray " << i;
        const sdf::SdfTraceResult cpu = sdf::traceSdf(atlas, kVolume, origin, direction);
        const bool gpuHit = gpu::asuint(gpuHits[i].y) != 0;
        agree += gpuHit == cpu.hit;
        if (gpuHit && cpu.hit) {
            ++bothHit;
            closeHits += std::abs(gpuHits[i].x - cpu.t) <= 0.25f * voxel;
        }
    }
    EXPECT_GE(agree, kRays * 99 / 100);
    EXPECT_GT(bothHit, kRays / 5);
    EXPECT_GE(closeHits, bothHit * 99 / 100);
}

LUMINA_INSTANTIATE_GPU_TEST(SdfGpuTest);

} // namespace
} // namespace lumina::test
