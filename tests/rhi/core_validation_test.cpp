// THE DELIBERATE-ERROR TEST of core validation (synchronization_validation_test.cpp has the
// synchronization one): with automatic barriers off, a texture is cleared without ever being put
// in the state a clear needs. Vulkan's core validation (an image cleared in
// TRANSFER_DST_OPTIMAL while it is still UNDEFINED) and D3D12's debug layer (a render target
// cleared in COMMON) must report it. Without a validation layer the test skips, saying so: the
// other GPU tests' "no validation messages" then proves nothing on that device.
#include "tests/rhi/gpu_test_fixture.h"

namespace lumina::test {
namespace {

using CoreValidationTest = GpuTest;

TEST_P(CoreValidationTest, ClearingATextureInTheWrongStateIsReported) {
    if (!device().capabilities().validationActive) {
        GTEST_SKIP() << "no validation layer on this " << rhi::apiName(GetParam())
                     << " device (D3D12: no debug layer, as under Wine, where CI loads the Vulkan layer "
                        "beneath vkd3d instead): a deliberate error cannot be checked";
    }
    expectValidationMessages();
    rhi::TextureHandle texture =
        device().createTexture({.format = rhi::Format::RGBA8_UNORM,
                                .width = 16,
                                .height = 16,
                                .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                .debugName = "cleared in the wrong state"});
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->setAutomaticBarriers(false);
    list->clearColor(*texture, {0.25f, 0.5f, 0.75f, 1.0f}); // no transition before it
    list->end();
    submitAndWait(*list);
    device().waitIdle();

    const std::vector<std::string> messages = validationMessages();
    EXPECT_GE(messages.size(), 1u) << "core validation missed a texture cleared in the wrong state";
    for (const std::string& message : messages) {
        EXPECT_EQ(message.find("SYNC-HAZARD"), std::string::npos)
            << "expected a core validation message, got a synchronization one: " << message;
    }
}

LUMINA_INSTANTIATE_GPU_TEST(CoreValidationTest);

} // namespace
} // namespace lumina::test
