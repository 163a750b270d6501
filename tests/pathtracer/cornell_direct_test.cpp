// The direct-only AOV of cornell_box_point (a point light, no emitters) at pixel centres is
// deterministic: rho / pi * I cos / d^2 where the light is visible, 0 where it is not (cos
// against the interpolated shading normal). Each pixel is recomputed on the CPU: the camera
// ray from the shared camera model, the hit and the shadow test through the CPU BVH queries. The floor (the
// plane y = 0, cos = h / d) is checked against the closed form of a plane under a point light, I h / d^3,
// without reference to the hit's normal. Also: direct + indirect = the radiance, and the albedo and normal
// AOVs are the hit's.
#include "gi/bvh/bvh_query.h"
#include "gi/core/camera.h"
#include "tests/pathtracer/path_tracer_fixture.h"

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_inverse.hpp>
#include <numbers>

namespace lumina::test {
namespace {

using CornellDirectTest = PathTracerTest;

constexpr uint32_t kSize = 48;
constexpr float kRelativeTolerance = 2e-4f;
// Scene units are millimetres: a hit this close to y = 0 is on the floor.
constexpr float kFloorEpsilon = 1e-2f;
// Pixels whose centre ray grazes an edge or a shadow boundary may go either way on the GPU
// and the CPU (different rounding): at most this fraction of them.
constexpr double kMaxDisagreement = 0.01;

TEST_P(CornellDirectTest, DirectAovMatchesAnalyticPointLight) {
    const scene::Scene scene = loadBuiltin("cornell_box_point", kSize, kSize);
    ASSERT_EQ(scene.lights.size(), 1u);
    const scene::Light& light = scene.lights.front();
    ASSERT_EQ(light.type, scene::LightType::Point);
    ASSERT_EQ(light.range, 0.0f);

    const gi::PathTracerScene traced(device(), scene);
    ASSERT_EQ(traced.stats().emitters, 0u);
    gi::PathTracerSettings settings;
    settings.jitter = false;
    settings.aovs = true;
    gi::PathTracer tracer(device(), traced, scene, settings);
    addSamples(tracer, 1);
    const image::Image result = tracer.readResult().image;

    const gpu::GpuCamera camera = gi::makeGpuCamera(scene.camera, kSize, kSize);
    const bvh::Bvh& bvh = traced.bvh();
    std::vector<uint32_t> meshFirstIndex; // GpuScene's index buffer: meshes one after another
    uint32_t indexCount = 0;
    for (const scene::Mesh& mesh : scene.meshes) {
        meshFirstIndex.push_back(indexCount);
        indexCount += uint32_t(mesh.indices.size());
    }
    uint32_t floorLit = 0, shadowed = 0, lit = 0, misses = 0, disagreements = 0;
    double indirectSum = 0.0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            bvh::Ray ray;
            ray.origin = gpu::cameraPosition(camera);
            ray.direction = gpu::cameraRayDirection(camera, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
            const bvh::RayHit hit = bvh::intersectClosest(bvh, ray);
            if (!hit.hit()) {
                ++misses; // past the box's open front: black sky, no AOVs
                EXPECT_EQ(result.at("direct.R", x, y), 0.0f) << "pixel " << x << ", " << y;
                EXPECT_EQ(result.at("albedo.R", x, y), 0.0f) << "pixel " << x << ", " << y;
                continue;
            }
            const gpu::BvhTriangle& tri = bvh.triangles[hit.triangle];
            const glm::vec3 v0(tri.v0), v1(tri.v1), v2(tri.v2);
            const glm::vec3 p = v0 + (v1 - v0) * hit.barycentrics.x + (v2 - v0) * hit.barycentrics.y;
            const gpu::PtTriangle ref = traced.geometry().refs[hit.primId];
            const uint32_t material = ref.info.z >> 8u;
            // Shading normal: the vertex normals interpolated and placed by the instance, on
            // the side the camera sees.
            const scene::Instance& instance = scene.instances[ref.info.x];
            const scene::Mesh& mesh = scene.meshes[instance.mesh];
            const uint32_t local = ref.info.y - meshFirstIndex[instance.mesh];
            const glm::vec3 objectNormal =
                mesh.normals[mesh.indices[local]] * (1.0f - hit.barycentrics.x - hit.barycentrics.y) +
                mesh.normals[mesh.indices[local + 1]] * hit.barycentrics.x +
                mesh.normals[mesh.indices[local + 2]] * hit.barycentrics.y;
            glm::vec3 n = glm::normalize(glm::inverseTranspose(glm::mat3(instance.transform)) * objectNormal);
            if (glm::dot(glm::cross(v1 - v0, v2 - v0), ray.direction) > 0.0f) {
                n = -n;
            }
            const glm::vec3 albedo(scene.materials[material].baseColor);

            const glm::vec3 toLight = light.position - p;
            const float d = glm::length(toLight);
            const glm::vec3 ng =
                glm::normalize(glm::cross(v1 - v0, v2 - v0)) *
                (glm::dot(glm::cross(v1 - v0, v2 - v0), ray.direction) > 0.0f ? -1.0f : 1.0f);
            bvh::Ray shadow;
            shadow.origin = p + ng * 1e-2f; // 10 micrometres off the surface
            shadow.direction = toLight / d;
            shadow.tMax = d;
            const bool visible = glm::dot(n, toLight) > 0.0f && glm::dot(ng, toLight) > 0.0f &&
                                 !bvh::intersectAny(bvh, shadow);
            glm::vec3 expected(0.0f);
            if (visible) {
                const bool onFloor = std::abs(p.y) < kFloorEpsilon;
                // On the floor: the closed form of a plane, cos = h / d.
                const float cosTheta = onFloor ? light.position.y / d : glm::dot(n, toLight) / d;
                expected = albedo * std::numbers::inv_pi_v<float> * light.strength() * cosTheta / (d * d);
                floorLit += onFloor;
                ++lit;
            } else {
                ++shadowed;
            }
            const glm::vec3 direct(result.at("direct.R", x, y), result.at("direct.G", x, y),
                                   result.at("direct.B", x, y));
            bool agree = true;
            for (int c = 0; c < 3; ++c) {
                agree =
                    agree && std::abs(direct[c] - expected[c]) <= kRelativeTolerance * expected[c] + 1e-7f;
            }
            const glm::vec3 gpuAlbedo(result.at("albedo.R", x, y), result.at("albedo.G", x, y),
                                      result.at("albedo.B", x, y));
            const glm::vec3 gpuNormal(result.at("normal.X", x, y), result.at("normal.Y", x, y),
                                      result.at("normal.Z", x, y));
            agree = agree && glm::all(glm::lessThan(glm::abs(gpuAlbedo - albedo), glm::vec3(1e-6f))) &&
                    glm::dot(gpuNormal, n) > 0.9999f;
            if (!agree) {
                ++disagreements;
                if (disagreements <= 5) {
                    std::printf("pixel (%u, %u): direct (%g, %g, %g), expected (%g, %g, %g)%s\n", x, y,
                                direct.x, direct.y, direct.z, expected.x, expected.y, expected.z,
                                visible ? "" : " (shadowed)");
                }
            }
            // The AOVs split the radiance.
            const image::Rgb total = result.rgbAt(x, y);
            const float indirect = result.at("indirect.R", x, y);
            EXPECT_NEAR(total.r, direct.r + indirect, 1e-5f * (total.r + 1.0f)) << "pixel " << x << ", " << y;
            indirectSum += indirect;
        }
    }
    std::printf("%u lit pixels (%u on the floor), %u shadowed, %u misses, %u disagreements\n", lit, floorLit,
                shadowed, misses, disagreements);
    EXPECT_LE(double(disagreements), kMaxDisagreement * kSize * kSize);
    EXPECT_GT(floorLit, kSize * kSize / 25) << "the floor should fill much of the image";
    EXPECT_GT(shadowed, kSize * kSize / 100) << "the blocks should cast shadows";
    EXPECT_GT(indirectSum, 0.0) << "light bounces";
}

LUMINA_INSTANTIATE_GPU_TEST(CornellDirectTest);

} // namespace
} // namespace lumina::test
