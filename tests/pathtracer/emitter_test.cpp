// An emissive quad (front face down) above a Lambertian plane: the plane's irradiance from a
// uniformly emitting polygon has a closed form (Lambert; Arvo, "Analytic Methods for
// Simulated Light Transport", 1995: E = Le/2 |sum_i theta_i n . gamma_i| over the edges), and
// the plane cannot see itself, so each plane pixel is rho / pi * E. This exercises emitter
// sampling by area, the BSDF samples that hit the emitter and their MIS weights together:
// the pixels must match within their measured standard errors.
#include "gi/core/camera.h"
#include "tests/pathtracer/path_tracer_fixture.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

namespace lumina::test {
namespace {

using EmitterTest = PathTracerTest;

constexpr uint32_t kSize = 32;
constexpr uint32_t kSpp = 32;
const glm::vec3 kAlbedo(0.7f, 0.5f, 0.3f);
const glm::vec3 kLe(4.0f, 3.0f, 2.0f);
constexpr double kSigmas = 4.0;

// A small quad far above, seen past from high up (emitter sampling carries most of the light),
// and a large quad close above, seen from between the two (BSDF samples carry much of it).
struct QuadSetup {
    const char* name;
    float quadHeight;
    float quadHalf;
    glm::vec3 quadCentre;
    glm::vec3 camera; // looking straight down
    float fovYDegrees;
};
const QuadSetup kSetups[] = {
    {"small quad far above", 0.8f, 0.3f, {0.2f, 0.8f, -0.1f}, {0.0f, 2.5f, 0.0f}, 60.0f},
    {"large quad close above", 0.25f, 0.6f, {0.05f, 0.25f, 0.0f}, {0.1f, 0.15f, -0.05f}, 90.0f},
};

scene::Mesh quadMesh(float y, float half, glm::vec3 centre, bool faceUp) {
    scene::Mesh mesh;
    mesh.positions = {centre + glm::vec3(-half, 0, -half), centre + glm::vec3(-half, 0, half),
                      centre + glm::vec3(half, 0, half), centre + glm::vec3(half, 0, -half)};
    for (glm::vec3& p : mesh.positions) {
        p.y = y;
    }
    mesh.normals.assign(4, glm::vec3(0, faceUp ? 1.0f : -1.0f, 0));
    mesh.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    // Counter-clockwise seen from +y for the first winding.
    mesh.indices = faceUp ? std::vector<uint32_t>{0, 1, 2, 0, 2, 3} : std::vector<uint32_t>{0, 2, 1, 0, 3, 2};
    for (const glm::vec3& p : mesh.positions) {
        mesh.bounds.extend(p);
    }
    return mesh;
}

scene::Scene makeScene(const QuadSetup& setup) {
    scene::Scene scene;
    scene.name = "plane under an emissive quad";
    scene.meshes.push_back(quadMesh(0.0f, 1.0f, glm::vec3(0.0f), true));
    scene.meshes.back().submeshes = {{0, 6, 0}};
    scene.meshes.push_back(quadMesh(setup.quadHeight, setup.quadHalf, setup.quadCentre, false));
    scene.meshes.back().submeshes = {{0, 6, 1}};
    scene.instances = {{0, glm::mat4(1.0f), "plane"}, {1, glm::mat4(1.0f), "light"}};
    scene::Material plane, light;
    plane.baseColor = glm::vec4(kAlbedo, 1.0f);
    light.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    light.emission = kLe;
    scene.materials = {plane, light};
    scene.camera.position = setup.camera;
    scene.camera.forward = {0.0f, -1.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.fovY = glm::radians(setup.fovYDegrees);
    scene.image = {kSize, kSize};
    return scene;
}

// Irradiance at p (normal +y) from the quad, by Lambert's polygon formula.
glm::vec3 quadIrradiance(const scene::Mesh& quad, glm::vec3 p) {
    double sum = 0.0;
    for (size_t i = 0; i < 4; ++i) {
        const glm::dvec3 a = glm::normalize(glm::dvec3(quad.positions[i] - p));
        const glm::dvec3 b = glm::normalize(glm::dvec3(quad.positions[(i + 1) % 4] - p));
        const double theta = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
        sum += theta * glm::normalize(glm::cross(a, b)).y;
    }
    return kLe * float(0.5 * std::abs(sum));
}

TEST_P(EmitterTest, PlaneUnderEmissiveQuadMatchesLambertsFormula) {
    for (const QuadSetup& setup : kSetups) {
        SCOPED_TRACE(setup.name);
        const scene::Scene scene = makeScene(setup);
        gi::PathTracerSettings settings;
        settings.jitter = false; // each pixel a point of the plane: the closed form applies
        settings.seed = 21;
        const gi::PathTracerResult result = render(scene, settings, kSpp);
        const gpu::GpuCamera camera = gi::makeGpuCamera(scene.camera, kSize, kSize);

        const char* channels[3][2] = {{"R", "variance.R"}, {"G", "variance.G"}, {"B", "variance.B"}};
        for (int c = 0; c < 3; ++c) {
            double error = 0.0, squaredError = 0.0, variance = 0.0, expectedSum = 0.0;
            uint32_t pixels = 0;
            for (uint32_t y = 0; y < kSize; ++y) {
                for (uint32_t x = 0; x < kSize; ++x) {
                    const glm::vec3 origin = gpu::cameraPosition(camera);
                    const glm::vec3 dir =
                        gpu::cameraRayDirection(camera, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
                    const glm::vec3 atQuad = origin + dir * ((setup.quadHeight - origin.y) / dir.y);
                    const glm::vec3 p = origin + dir * (-origin.y / dir.y);
                    const float margin = 0.02f; // keep clear of the edges, where rounding decides
                    if (origin.y > setup.quadHeight &&
                        std::abs(atQuad.x - setup.quadCentre.x) < setup.quadHalf + margin &&
                        std::abs(atQuad.z - setup.quadCentre.z) < setup.quadHalf + margin) {
                        continue; // the quad's back: black
                    }
                    if (std::abs(p.x) > 1.0f - margin || std::abs(p.z) > 1.0f - margin) {
                        continue; // the sky or the plane's edge
                    }
                    const double expected =
                        kAlbedo[c] * std::numbers::inv_pi * quadIrradiance(scene.meshes[1], p)[c];
                    const double value = result.image.at(channels[c][0], x, y);
                    error += value - expected;
                    squaredError += (value - expected) * (value - expected);
                    variance += result.image.at(channels[c][1], x, y);
                    expectedSum += expected;
                    ++pixels;
                }
            }
            ASSERT_GT(pixels, kSize * kSize / 3);
            const double meanError = error / pixels, standardError = std::sqrt(variance) / pixels;
            const double ratio = squaredError / variance;
            std::printf(
                "%s, %s: %u pixels, mean %.5f, mean error %.6f, standard error %.6f, spread/variance %.3f\n",
                setup.name, channels[c][0], pixels, expectedSum / pixels, meanError, standardError, ratio);
            EXPECT_NEAR(meanError, 0.0, kSigmas * standardError) << channels[c][0];
            EXPECT_LT(standardError, 0.01 * expectedSum / pixels) << channels[c][0] << ": the test has power";
            EXPECT_GT(ratio, 0.7) << channels[c][0];
            EXPECT_LT(ratio, 1.4) << channels[c][0];
        }
        EXPECT_EQ(result.nonFiniteSamples, 0u);
    }
}

LUMINA_INSTANTIATE_GPU_TEST(EmitterTest);

} // namespace
} // namespace lumina::test
