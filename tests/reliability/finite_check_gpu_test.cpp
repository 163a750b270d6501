// The finite check of `lumina render --check-finite` (gi/core/finite_check.h): quiet on a clean
// frame, and on a poisoned one it names the first pass that wrote a NaN or Inf. The poison goes in
// behind the renderer's back (GpuScene::recordMaterial with a NaN emission, which
// FrameRenderer::setEmission would refuse), as a bug in an upload would put it there.
#include "gi/frame/frame_finite_check.h"
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <limits>
#include <string>

namespace lumina::test {
namespace {

using FiniteCheckGpu = GpuTest;

constexpr uint32_t kSize = 32;

TEST_P(FiniteCheckGpu, ACleanFrameIsQuiet) {
    LUMINA_REQUIRE_KERNELS();
    FrameHarness h(device(), shaders(), scene::loadScene("cornell_box"),
                   {.width = kSize, .height = kSize, .checkFinite = true});
    gi::watchFloatBuffers(*h.finiteCheck(), h.renderer());
    h.render(3);
    EXPECT_FALSE(h.nonFinite()) << h.nonFinite()->describe();
    EXPECT_GT(h.finiteCheck()->checksLastFrame(), 10u) << "the check must see the frame's passes";
}

TEST_P(FiniteCheckGpu, ANanEmissionUploadedBehindTheRenderersBackIsNamed) {
    LUMINA_REQUIRE_KERNELS();
    const scene::Scene scene = scene::loadScene("cornell_box");
    FrameHarness h(device(), shaders(), scene, {.width = kSize, .height = kSize, .checkFinite = true});
    h.render(2);
    ASSERT_FALSE(h.nonFinite()) << h.nonFinite()->describe();

    uint32_t light = 0;
    while (light < scene.materials.size() && scene.materials[light].name != "light") {
        ++light;
    }
    ASSERT_LT(light, scene.materials.size());
    scene::Material poisoned = scene.materials[light];
    poisoned.emission.x = std::numeric_limits<float>::quiet_NaN();
    rhi::CommandListHandle upload = device().createCommandList();
    upload->begin();
    h.gpuScene().recordMaterial(*upload, light, poisoned);
    upload->end();
    rhi::IQueue& queue = device().queue(upload->queueType());
    queue.waitForValue(queue.submit(*upload));

    h.render();
    ASSERT_TRUE(h.nonFinite()) << "a NaN emission must show in some pass's output";
    const std::string what = h.nonFinite()->describe();
    std::printf("%s\n", what.c_str());
    // The GBuffer resolve writes the emission into the material target first (measured).
    EXPECT_EQ(h.nonFinite()->pass, "gbuffer resolve") << what;
    EXPECT_NE(h.nonFinite()->resource.find("gbuffer material"), std::string::npos) << what;
    EXPECT_GT(h.nonFinite()->count, 0u);
}

LUMINA_INSTANTIATE_GPU_TEST(FiniteCheckGpu);

} // namespace
} // namespace lumina::test
