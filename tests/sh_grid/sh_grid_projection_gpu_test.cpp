// The SH grid's projection kernels on lavapipe (docs/sh_grid.md, "Tests"): radiance written onto
// the six cube faces of a probe, projected by sh_grid_project_face and combined by sh_grid_combine
// exactly as a bake does, against closed forms:
//   - constant radiance M: E_00 = pi x 2 sqrt(pi) M, every other coefficient 0;
//   - a clamped cosine lobe max(0, d.a): L_lm = A_l Y_lm(a), so E_lm = A_l^2 Y_lm(a);
//   - round trip: the radiance whose irradiance is a known set of coefficients gives them back.
// Faces are 64^2 RGBA32F (the bake writes RGBA16F; the kernel reads either).
#include "gi/core/camera.h"
#include "gi/core/frame_context.h"
#include "gi/core/gpu_resources.h"
#include "gi/core/pipeline_cache.h"
#include "gi/sh_grid/sh_grid_bake.h"
#include "gi/sh_grid/sh_grid_combine_pass.h"
#include "gi/sh_grid/sh_grid_project_face_pass.h"
#include "rhi/transfer.h"
#include "shaders/sh_grid/sh_grid_shared.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

namespace lumina::test {
namespace {

constexpr uint32_t kFace = 64;
constexpr uint32_t kProbe = 3; // of a 2^3 grid: any slot but the first

using Radiance = std::function<glm::vec3(const glm::vec3&)>;

class ShGridProjectionGpu : public GpuTest {
protected:
    // The nine irradiance coefficients (rgb) the kernels make of `radiance`.
    std::vector<glm::vec3> project(const Radiance& radiance) {
        rhi::IDevice& dev = device();
        const gi::ShGridLayout layout{
            .origin = glm::vec3(0.0f), .spacing = glm::vec3(1.0f), .counts = glm::uvec3(2)};
        const gi::ShGridResources r = gi::ShGridResources::create(dev, layout, 8, 8);
        const gi::GBuffer gbuffer = gi::GBuffer::create(dev, kFace, kFace); // bound, not read (no bounce)
        gi::PipelineCache pipelines(dev, shaders());
        rhi::CommandListHandle list = dev.createCommandList();
        std::vector<rhi::TextureHandle> faces;
        std::vector<gpu::ShGridFaceConstants> constants;
        for (uint32_t face = 0; face < LUMINA_SH_GRID_FACES; ++face) {
            const gpu::GpuCamera camera =
                gi::makeGpuCamera(gi::shGridFaceCamera(glm::vec3(0.0f), face, 0.01f, 10.0f), kFace, kFace);
            constants.push_back(gi::shGridFaceConstants(camera, face, kFace, false));
            const gpu::ShGridFaceConstants& c = constants.back();
            std::vector<glm::vec4> texels;
            for (uint32_t y = 0; y < kFace; ++y) {
                for (uint32_t x = 0; x < kFace; ++x) {
                    const float u = 2.0f * (float(x) + 0.5f) / float(kFace) - 1.0f;
                    const float v = 1.0f - 2.0f * (float(y) + 0.5f) / float(kFace);
                    const glm::vec3 d =
                        glm::normalize(glm::vec3(c.forward) + u * glm::vec3(c.right) + v * glm::vec3(c.up));
                    texels.emplace_back(radiance(d), 1.0f);
                }
            }
            faces.push_back(
                gi::createStorageTexture2d(dev, rhi::Format::RGBA32_FLOAT, kFace, kFace, "test face"));
            rhi::writeTexture(dev, *faces.back(), {}, texels.data());
        }
        list->begin();
        gi::FrameContext frame(pipelines, *list, 0);
        const gpu::ShGridConstants grid{};
        list->writeBuffer(*r.constants, &grid, sizeof(grid));
        const std::vector<glm::vec4> zeros(size_t(layout.probes()) * LUMINA_SH_GRID_COEFFICIENTS,
                                           glm::vec4(0.0f));
        list->writeBuffer(*r.coefficients, zeros.data(), zeros.size() * sizeof(glm::vec4));
        for (uint32_t face = 0; face < LUMINA_SH_GRID_FACES; ++face) {
            gi::ShGridProjectFacePass().record(frame, r, faces[face], gbuffer, constants[face]);
        }
        gi::ShGridCombinePass().record(frame, r, kProbe);
        list->end();
        submitAndWait(*list);
        const std::vector<glm::vec4> all = readBack<glm::vec4>(*r.coefficients);
        std::vector<glm::vec3> out;
        for (uint32_t k = 0; k < LUMINA_SH_GRID_COEFFICIENTS; ++k) {
            out.emplace_back(all[kProbe * LUMINA_SH_GRID_COEFFICIENTS + k]);
        }
        return out;
    }
};

float worstError(const std::vector<glm::vec3>& got, const std::vector<glm::vec3>& expected) {
    float worst = 0.0f;
    for (size_t k = 0; k < expected.size(); ++k) {
        const glm::vec3 e = glm::abs(got[k] - expected[k]);
        worst = std::max({worst, e.x, e.y, e.z});
        std::printf("  k=%zu got (%.5f %.5f %.5f) expected (%.5f %.5f %.5f)\n", k, got[k].x, got[k].y,
                    got[k].z, expected[k].x, expected[k].y, expected[k].z);
    }
    return worst;
}

TEST_P(ShGridProjectionGpu, ConstantRadianceGivesPiTimesItInEveryDirection) {
    LUMINA_REQUIRE_KERNELS();
    const glm::vec3 m(1.0f, 0.5f, 2.0f);
    const std::vector<glm::vec3> got = project([&](const glm::vec3&) { return m; });
    std::vector<glm::vec3> expected(LUMINA_SH_GRID_COEFFICIENTS, glm::vec3(0.0f));
    expected[0] = float(std::numbers::pi) * LUMINA_SH_SPHERE_INTEGRAL_0 * m;
    const float worst = worstError(got, expected);
    std::printf("constant radiance: worst coefficient error %.2e (E_00 %.5f)\n", worst, expected[0].z);
    EXPECT_LE(worst, 2e-4f * expected[0].z);
    // Evaluated in any direction: E = pi M.
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f));
    glm::vec3 e(0.0f);
    for (uint32_t k = 0; k < LUMINA_SH_GRID_COEFFICIENTS; ++k) {
        e += got[k] * gpu::shBasis(k, n);
    }
    EXPECT_NEAR(e.z / (float(std::numbers::pi) * m.z), 1.0f, 1e-4f);
}

TEST_P(ShGridProjectionGpu, CosineLobeMatchesItsClosedForm) {
    LUMINA_REQUIRE_KERNELS();
    const glm::vec3 axis = glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f));
    const glm::vec3 tint(1.0f, 0.25f, 0.5f);
    const std::vector<glm::vec3> got =
        project([&](const glm::vec3& d) { return tint * std::max(0.0f, glm::dot(d, axis)); });
    std::vector<glm::vec3> expected;
    for (uint32_t k = 0; k < LUMINA_SH_GRID_COEFFICIENTS; ++k) {
        const float a = gpu::shCosineBand(k);
        expected.push_back(tint * (a * a * gpu::shBasis(k, axis)));
    }
    const float worst = worstError(got, expected);
    std::printf("cosine lobe: worst coefficient error %.2e of E_00 %.5f\n", worst, expected[0].x);
    // The lobe's kink at the horizon crosses texels: a few 1e-4 of E_00 at 64^2 faces.
    EXPECT_LE(worst, 2e-3f * expected[0].x);
}

TEST_P(ShGridProjectionGpu, KnownIrradianceRoundTrips) {
    LUMINA_REQUIRE_KERNELS();
    const std::array<glm::vec3, LUMINA_SH_GRID_COEFFICIENTS> irradiance = {
        glm::vec3(3.0f, 2.0f, 1.0f),   glm::vec3(0.5f, -0.2f, 0.1f), glm::vec3(-0.4f, 0.3f, 0.2f),
        glm::vec3(0.25f, 0.1f, -0.3f), glm::vec3(0.1f, 0.05f, 0.0f), glm::vec3(-0.1f, 0.2f, 0.15f),
        glm::vec3(0.2f, -0.1f, 0.05f), glm::vec3(0.0f, 0.1f, -0.2f), glm::vec3(-0.15f, 0.05f, 0.1f)};
    // The radiance whose irradiance that is: L_k = E_k / A_l.
    const std::vector<glm::vec3> got = project([&](const glm::vec3& d) {
        glm::vec3 l(0.0f);
        for (uint32_t k = 0; k < LUMINA_SH_GRID_COEFFICIENTS; ++k) {
            l += irradiance[k] * (gpu::shBasis(k, d) / gpu::shCosineBand(k));
        }
        return l;
    });
    const float worst = worstError(got, {irradiance.begin(), irradiance.end()});
    std::printf("round trip: worst coefficient error %.2e\n", worst);
    EXPECT_LE(worst, 1e-3f);
}

LUMINA_INSTANTIATE_GPU_TEST(ShGridProjectionGpu);

} // namespace
} // namespace lumina::test
