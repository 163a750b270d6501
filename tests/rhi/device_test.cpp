// Adapters, device identity and capabilities.
#include "tests/rhi/gpu_test_fixture.h"

#include <iostream>

namespace lumina::test {
namespace {

using DeviceTest = GpuTest;

TEST_P(DeviceTest, AdaptersAreListedWithNamesDriversAndVersions) {
    const std::vector<rhi::AdapterInfo> adapters = app::listAdapters(GetParam());
    ASSERT_FALSE(adapters.empty());
    for (size_t i = 0; i < adapters.size(); ++i) {
        SCOPED_TRACE(adapters[i].name);
        std::cout << "[ info ] adapter " << i << ": " << adapters[i].name << " (" << adapters[i].driver
                  << ", API " << adapters[i].apiVersion << ", " << rhi::adapterTypeName(adapters[i].type)
                  << ", " << adapters[i].dedicatedMemoryBytes / (1024 * 1024) << " MiB device-local)\n";
        EXPECT_EQ(adapters[i].index, i);
        EXPECT_FALSE(adapters[i].name.empty());
        EXPECT_FALSE(adapters[i].driver.empty());
        EXPECT_FALSE(adapters[i].apiVersion.empty());
    }
    EXPECT_EQ(device().adapter().name, adapters[0].name);
    EXPECT_EQ(device().adapter().deviceId, adapters[0].deviceId);
    EXPECT_EQ(device().api(), GetParam());
}

TEST_P(DeviceTest, CapabilitiesAreReported) {
    const rhi::DeviceCapabilities& caps = device().capabilities();
    // D3D12 reports 0 where the device has no wave intrinsics (Wine's vkd3d, shader model 5.1).
    const bool dxbcOnly = GetParam() == rhi::Api::D3D12 && caps.shaderFormat == rhi::ShaderFormat::Dxbc;
    if (!dxbcOnly) {
        EXPECT_GT(caps.subgroupSize, 0u);
    }
    EXPECT_GT(caps.timestampPeriodNs, 0.0);
    EXPECT_GE(caps.maxPushConstantBytes, 128u);
    EXPECT_GE(caps.maxTexture2DSize, 4096u);
    EXPECT_GE(caps.maxTexture3DSize, 256u);
    if (GetParam() == rhi::Api::Vulkan) {
        EXPECT_EQ(caps.shaderFormat, rhi::ShaderFormat::Spirv);
    } else {
        // DXIL on shader model 6; DXBC on devices below it (Wine's vkd3d).
        EXPECT_NE(caps.shaderFormat, rhi::ShaderFormat::Spirv);
    }
}

TEST_P(DeviceTest, QueuesReportTheirTypes) {
    for (const rhi::QueueType type :
         {rhi::QueueType::Graphics, rhi::QueueType::Compute, rhi::QueueType::Copy}) {
        EXPECT_EQ(device().queue(type).type(), type);
        EXPECT_EQ(device().queue(type).completedValue(), 0u);
    }
}

TEST_P(DeviceTest, EmptySubmissionsSignalInOrder) {
    rhi::IQueue& queue = device().queue(rhi::QueueType::Graphics);
    const uint64_t first = queue.submit(std::span<rhi::ICommandList* const>{});
    const uint64_t second = queue.submit(std::span<rhi::ICommandList* const>{});
    EXPECT_LT(first, second);
    queue.waitForValue(second);
    EXPECT_GE(queue.completedValue(), second);
    device().waitIdle();
}

TEST_P(DeviceTest, SubmittingAListThatHasNotEndedThrows) {
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    EXPECT_THROW(device().queue(rhi::QueueType::Graphics).submit(*list), rhi::Error);
    list->end();
    submitAndWait(*list);
}

TEST_P(DeviceTest, BindingLayoutsOfEveryKindAreCreated) {
    // Descriptor-set layouts on Vulkan, root signatures on D3D12: every binding type, several
    // register spaces, each visibility.
    const std::vector<rhi::BindingLayoutItem> everyType = {
        {rhi::BindingType::ConstantBuffer, 0}, {rhi::BindingType::ConstantBuffer, 1},
        {rhi::BindingType::TextureSRV, 0},     {rhi::BindingType::BufferSRV, 1},
        {rhi::BindingType::RawBufferSRV, 2},   {rhi::BindingType::TextureUAV, 0},
        {rhi::BindingType::BufferUAV, 1},      {rhi::BindingType::RawBufferUAV, 2},
        {rhi::BindingType::Sampler, 0},        {rhi::BindingType::Sampler, 1},
    };
    for (const rhi::ShaderStageMask visibility : {rhi::ShaderStageMask::Compute, rhi::ShaderStageMask::Vertex,
                                                  rhi::ShaderStageMask::Pixel, rhi::ShaderStageMask::All}) {
        for (uint32_t space = 0; space < 3; ++space) {
            rhi::BindingLayoutHandle layout =
                device().createBindingLayout({.space = space, .visibility = visibility, .items = everyType});
            ASSERT_TRUE(layout);
            EXPECT_EQ(layout->desc().items.size(), everyType.size());
            EXPECT_EQ(layout->desc().space, space);
        }
    }
    rhi::BindingLayoutHandle samplersOnly = device().createBindingLayout(
        {.space = 1, .visibility = rhi::ShaderStageMask::Pixel, .items = {{rhi::BindingType::Sampler, 0}}});
    rhi::BindingLayoutHandle empty =
        device().createBindingLayout({.space = 2, .visibility = rhi::ShaderStageMask::All, .items = {}});
    EXPECT_TRUE(samplersOnly && empty);
}

TEST_P(DeviceTest, ValidationMessageCountStartsAtZero) {
    EXPECT_EQ(device().validationMessageCount(), 0u);
}

LUMINA_INSTANTIATE_GPU_TEST(DeviceTest);

} // namespace
} // namespace lumina::test
