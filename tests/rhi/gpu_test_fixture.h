#pragma once
// The fixture of every GPU test in the project: a device on the backend under test with
// validation and synchronization validation on. Every validation message is recorded, and
// any message fails the test unless the test declared it provokes them on purpose.
//
//   class MyPassTest : public lumina::test::GpuTest {};
//   TEST_P(MyPassTest, DoesTheThing) { auto& dev = device(); ... }
//   LUMINA_INSTANTIATE_GPU_TEST(MyPassTest);   // one instance per compiled-in backend
//
// Tests with more parameters derive from GpuTestFixture and call openDevice(api) in SetUp.
//
// Each test gets its own device, and ctest runs each test in its own process. Running a
// whole GPU test binary in one process works on lavapipe, but on an NVIDIA H100 (driver
// 580, sandboxed) instance creation failed after about 30 devices in one process.
#include "app/backends.h"
#include "rhi/rhi.h"

#include <gtest/gtest.h>
#include <memory>
#include <mutex>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::test {

// A compute pipeline with one binding layout (space 0), as most test kernels need.
struct ComputeKernel {
    rhi::BindingLayoutHandle layout;
    rhi::ComputePipelineHandle pipeline;
};

class GpuTestFixture : public ::testing::Test {
protected:
    // Creates the device (validation and synchronization validation on, unless a long run on the
    // lent GPU asks for its own frame times: tests/frame/dynamic_long_run_test.cpp) and the
    // kernel library.
    void openDevice(rhi::Api api, bool validation = true);
    // Destroys the device, then fails the test if validation reported anything unexpected.
    void TearDown() override;

    rhi::IDevice& device();
    rhi::ShaderLibrary& shaders();

    // Why this device cannot run the build's kernels, or empty when it can. D3D12 devices skip
    // kernel tests where the build made no kernels in a format they take (DXIL, or DXBC from
    // vkd3d-compiler: .ci/install-dxbc-tools.sh); a Vulkan build always has SPIR-V, so a
    // missing .spv fails instead.
    std::string kernelsUnavailable();
    // The same for one kernel: why this D3D12 device cannot load `name` (the build could not
    // compile it to DXBC, say), or empty. Always empty on Vulkan.
    std::string kernelUnavailable(std::string_view name);

    // The test provokes validation messages on purpose: they no longer fail it.
    void expectValidationMessages() { expectMessages_ = true; }
    std::vector<std::string> validationMessages() const;

    // Submits to the list's queue and waits for it on the CPU.
    void submitAndWait(rhi::ICommandList& list);
    // A compute kernel by name ("rhi_tests/chain_step"), its layout holding `items`.
    ComputeKernel loadComputeKernel(std::string_view name, std::vector<rhi::BindingLayoutItem> items,
                                    uint32_t pushConstantBytes = 0);

    template <typename T>
    std::vector<T> readBack(rhi::IBuffer& buffer) {
        return rhi::readBufferAs<T>(device(), buffer);
    }

private:
    rhi::DeviceHandle device_;
    std::unique_ptr<rhi::ShaderLibrary> shaders_;
    // Shared with the device's message callback, which may outlive nothing but may run on
    // any thread.
    struct MessageLog {
        std::mutex mutex;
        std::vector<std::string> messages;
    };
    std::shared_ptr<MessageLog> log_ = std::make_shared<MessageLog>();
    bool expectMessages_ = false;
};

class GpuTest : public GpuTestFixture, public ::testing::WithParamInterface<rhi::Api> {
protected:
    void SetUp() override { openDevice(GetParam()); }
};

// "vulkan", "d3d12": the suffix of each parameterised test's name.
std::string apiName(const ::testing::TestParamInfo<rhi::Api>& info);

} // namespace lumina::test

namespace lumina::rhi {
// Readable parameters in gtest's messages ("vulkan", not "1-byte object <00>").
inline void PrintTo(Api api, std::ostream* out) {
    *out << apiName(api);
}
inline void PrintTo(Format format, std::ostream* out) {
    *out << formatInfo(format).name;
}
} // namespace lumina::rhi

// First line of every test (or SetUp) that loads kernels.
#define LUMINA_REQUIRE_KERNELS()                                                                             \
    do {                                                                                                     \
        if (const std::string kernelsMissing = kernelsUnavailable(); !kernelsMissing.empty()) {              \
            GTEST_SKIP() << kernelsMissing;                                                                  \
        }                                                                                                    \
    } while (false)

// First line of a test that needs one kernel the D3D12 build may lack (docs/d3d12.md lists them).
#define LUMINA_REQUIRE_KERNEL(name)                                                                          \
    do {                                                                                                     \
        if (const std::string kernelMissing = kernelUnavailable(name); !kernelMissing.empty()) {             \
            GTEST_SKIP() << kernelMissing;                                                                   \
        }                                                                                                    \
    } while (false)

#define LUMINA_INSTANTIATE_GPU_TEST(Suite)                                                                   \
    INSTANTIATE_TEST_SUITE_P(Backends, Suite, ::testing::ValuesIn(::lumina::app::compiledApis()),            \
                             ::lumina::test::apiName)
