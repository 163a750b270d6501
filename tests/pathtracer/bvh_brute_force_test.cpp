// The path tracer's GPU scene BVH (every instance's triangles in world space, uploaded by
// PathTracerScene, traversed by shaders/common/bvh_traversal.hlsli, read back through the
// path tracer's surface reader) against brute force on the CPU: every triangle of every
// instance tested against every ray. Checks the hit distance, which instance and triangle
// was hit, its material and its front-face normal, on a scene with instancing, non-uniform
// scale and mirroring transforms.
#include "gi/core/frame_context.h"
#include "gi/scene/scene_loader.h"
#include "shaders/common/bvh_shared.h"
#include "shaders/common/constants_shared.h"
#include "shaders/common/ray_triangle.hlsli"
#include "tests/bvh/test_meshes.h"
#include "tests/pathtracer/path_tracer_fixture.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

namespace lumina::test {
namespace {

using BvhBruteForceTest = PathTracerTest;

constexpr uint32_t kRays = 2048;
constexpr uint32_t kGroupSize = LUMINA_LINEAR_GROUP_SIZE; // numthreads of pathtracer/ray_query

// The Cornell box plus instances of an icosphere: rotated, stretched, two of them mirrored.
scene::Scene makeScene() {
    scene::Scene scene = scene::loadScene("cornell_box");
    const Mesh sphere = makeIcosphere(glm::vec3(0.0f), 1.0f, 2);
    scene::Mesh mesh;
    mesh.name = "icosphere";
    mesh.positions = sphere.positions;
    for (const glm::vec3& p : sphere.positions) {
        mesh.normals.push_back(glm::normalize(p));
        mesh.uvs.emplace_back(0.0f);
        mesh.bounds.extend(p);
    }
    mesh.indices = sphere.indices;
    const auto material = uint32_t(scene.materials.size());
    scene::Material red;
    red.name = "sphere";
    red.baseColor = glm::vec4(0.9f, 0.1f, 0.1f, 1.0f);
    scene.materials.push_back(red);
    mesh.submeshes = {{0, uint32_t(mesh.indices.size()), material}};
    const auto meshIndex = uint32_t(scene.meshes.size());
    scene.meshes.push_back(mesh);

    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 6; ++i) {
        glm::mat4 t =
            glm::translate(glm::mat4(1.0f), glm::vec3(80.0f + 400.0f * unit(rng), 60.0f + 400.0f * unit(rng),
                                                      60.0f + 400.0f * unit(rng)));
        t = glm::rotate(t, 6.28f * unit(rng),
                        glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + 0.1f));
        glm::vec3 scale(30.0f + 50.0f * unit(rng), 30.0f + 50.0f * unit(rng), 30.0f + 50.0f * unit(rng));
        if (i % 3 == 1) {
            scale.x = -scale.x; // mirrors: flips the winding in world space
        }
        scene.instances.push_back({meshIndex, glm::scale(t, scale), "sphere " + std::to_string(i)});
    }
    return scene;
}

struct CpuHit {
    float t = INFINITY;
    uint32_t instance = LUMINA_BVH_NO_HIT;
    uint32_t firstIndex = 0; // position of the triangle's first index in the GpuScene index buffer
    uint32_t material = 0;
    glm::vec3 frontNormal{0.0f};
};

CpuHit bruteForce(const scene::Scene& scene, const std::vector<uint32_t>& meshFirstIndex,
                  const gpu::BvhRay& ray) {
    const glm::vec3 origin(ray.originAndTMin);
    const gpu::WatertightRay wray = gpu::makeWatertightRay(origin, glm::vec3(ray.directionAndTMax));
    CpuHit best;
    best.t = ray.directionAndTMax.w;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        const scene::Mesh& mesh = scene.meshes[instance.mesh];
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(instance.transform));
        for (const scene::Submesh& submesh : mesh.submeshes) {
            for (uint32_t k = submesh.firstIndex; k < submesh.firstIndex + submesh.indexCount; k += 3) {
                glm::vec3 v[3], p[3];
                for (int c = 0; c < 3; ++c) {
                    p[c] = mesh.positions[mesh.indices[k + c]];
                    v[c] = glm::vec3(instance.transform * glm::vec4(p[c], 1.0f));
                }
                float t;
                glm::vec2 bary;
                if (gpu::intersectTriangleWatertight(wray, v[0], v[1], v[2], ray.originAndTMin.w, best.t, t,
                                                     bary)) {
                    best.t = t;
                    best.instance = i;
                    best.firstIndex = meshFirstIndex[instance.mesh] + k;
                    best.material = submesh.material;
                    // The front face is where the object-space face normal goes under the normal matrix.
                    best.frontNormal = glm::normalize(normalMatrix * glm::cross(p[1] - p[0], p[2] - p[0]));
                }
            }
        }
    }
    return best;
}

TEST_P(BvhBruteForceTest, SceneBvhMatchesBruteForce) {
    const scene::Scene scene = makeScene();
    const gi::PathTracerScene traced(device(), scene);
    std::vector<uint32_t> meshFirstIndex;
    uint32_t indexCount = 0;
    for (const scene::Mesh& mesh : scene.meshes) {
        meshFirstIndex.push_back(indexCount);
        indexCount += uint32_t(mesh.indices.size());
    }

    std::mt19937 rng(17);
    std::uniform_real_distribution<float> position(-50.0f, 600.0f);
    std::vector<gpu::BvhRay> rays(kRays);
    for (uint32_t i = 0; i < kRays; ++i) {
        const glm::vec3 origin(position(rng), position(rng), position(rng) - (i % 4 == 0 ? 800.0f : 0.0f));
        const float tMax = (i % 5 == 0) ? 200.0f : 1e30f;
        rays[i] = {glm::vec4(origin, 0.0f), glm::vec4(randomUnitVector(rng), tMax)};
    }
    const rhi::BufferHandle rayBuffer = rhi::createBufferWithData(device(),
                                                                  {.size = kRays * sizeof(gpu::BvhRay),
                                                                   .structStride = sizeof(gpu::BvhRay),
                                                                   .usage = rhi::BufferUsage::Structured,
                                                                   .debugName = "test rays"},
                                                                  rays.data(), kRays * sizeof(gpu::BvhRay));
    const rhi::BufferHandle hits =
        device().createBuffer({.size = 2 * kRays * sizeof(gpu::float4),
                               .structStride = sizeof(gpu::float4),
                               .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                               .debugName = "test hits"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    {
        gi::FrameContext frame(pipelines(), *list, 0);
        const gi::GpuScene& gpuScene = traced.gpuScene();
        frame.compute("path tracer: ray query", "pathtracer/ray_query")
            .read(0, traced.bvhNodes)
            .read(1, traced.bvhTriangles)
            .read(2, traced.triangles)
            .read(3, gpuScene.vertices)
            .read(4, gpuScene.indices)
            .read(5, gpuScene.instances)
            .read(6, rayBuffer)
            .write(0, hits)
            .constants(gpu::PtRayQueryConstants{kRays, 0, 0, 0})
            .dispatch((kRays + kGroupSize - 1) / kGroupSize);
    }
    list->end();
    submitAndWait(*list);
    const std::vector<gpu::float4> gpuHits = readBack<gpu::float4>(*hits);
    ASSERT_EQ(gpuHits.size(), 2 * kRays);
    const std::vector<gpu::PtTriangle>& refs = traced.geometry().refs;

    uint32_t hitCount = 0, hitMismatches = 0, triangleMismatches = 0, sphereHits = 0;
    for (uint32_t i = 0; i < kRays; ++i) {
        const CpuHit cpu = bruteForce(scene, meshFirstIndex, rays[i]);
        const gpu::float4 first = gpuHits[2 * i];
        const gpu::float4 second = gpuHits[2 * i + 1];
        const uint32_t prim = gpu::asuint(first.w);
        const bool cpuHit = cpu.instance != LUMINA_BVH_NO_HIT;
        if (cpuHit != (prim != LUMINA_BVH_NO_HIT)) {
            ++hitMismatches;
            continue;
        }
        if (!cpuHit) {
            continue;
        }
        ++hitCount;
        EXPECT_NEAR(first.x, cpu.t, 1e-5f * cpu.t) << "ray " << i;
        ASSERT_LT(prim, refs.size()) << "ray " << i;
        const gpu::PtTriangle ref = refs[prim];
        if (ref.info.x != cpu.instance || ref.info.y != cpu.firstIndex) {
            ++triangleMismatches; // a ray through a shared edge may name either triangle
            continue;
        }
        sphereHits += scene.instances[cpu.instance].mesh == scene.meshes.size() - 1;
        EXPECT_EQ(gpu::asuint(second.w), cpu.material) << "ray " << i;
        EXPECT_GT(glm::dot(glm::vec3(second), cpu.frontNormal), 0.9999f)
            << "ray " << i << ": front normal (" << second.x << ", " << second.y << ", " << second.z << ")";
    }
    EXPECT_LE(hitMismatches, kRays / 1000);
    EXPECT_LE(triangleMismatches, kRays / 500);
    EXPECT_GT(hitCount, kRays / 3);
    EXPECT_GT(sphereHits, 20u) << "the instanced spheres should be hit too";
}

LUMINA_INSTANTIATE_GPU_TEST(BvhBruteForceTest);

} // namespace
} // namespace lumina::test
