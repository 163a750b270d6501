// The kernel library: which file a kernel loads from on each device, and what it says when a
// kernel cannot be loaded (docs/d3d12.md, "DXBC and the Wine run").
#include "rhi/error.h"
#include "rhi/shader_library.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <filesystem>
#include <fstream>
#include <string>

namespace lumina::test {
namespace {

using ShaderLibraryTest = GpuTest;

// A fresh, empty kernel folder for one test, removed afterwards.
class KernelFolder {
public:
    KernelFolder() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string("lumina-kernels-") + info->name();
        for (char& c : name) {
            c = (c == '/' || c == '\\') ? '-' : c;
        }
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~KernelFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    const std::filesystem::path& path() const { return path_; }
    void write(const std::string& file, const std::string& text) const {
        std::ofstream(path_ / file, std::ios::binary) << text;
    }

private:
    std::filesystem::path path_;
};

TEST_P(ShaderLibraryTest, AMissingKernelNamesTheFilesLookedFor) {
    const KernelFolder folder;
    rhi::ShaderLibrary library(device(), folder.path());
    const std::string reason = library.unavailableReason("nowhere/kernel");
    const char* expected = GetParam() == rhi::Api::Vulkan ? "nowhere/kernel.spv" : "nowhere/kernel.dxbc";
    EXPECT_NE(reason.find(expected), std::string::npos) << reason;
    try {
        library.get("nowhere/kernel");
        FAIL() << "loading a kernel that does not exist did not throw";
    } catch (const rhi::Error& error) {
        EXPECT_EQ(std::string(error.what()), reason);
    }
}

TEST_P(ShaderLibraryTest, TheBuildsReasonForNoDxbcIsReportedOnD3D12) {
    const KernelFolder folder;
    folder.write("kernel.dxbc.unavailable", "this compiler cannot read raw UAVs\n");
    rhi::ShaderLibrary library(device(), folder.path());
    const std::string reason = library.unavailableReason("kernel");
    if (GetParam() == rhi::Api::D3D12) {
        EXPECT_EQ(reason, "kernel 'kernel' has no kernel.dxbc: this compiler cannot read raw UAVs");
    } else {
        EXPECT_NE(reason.find("not found: no kernel.spv"), std::string::npos) << reason;
    }
}

// DXBC runs on every D3D12 device, so a kernel the build made only as DXBC loads also where
// the device would prefer DXIL (shader model 6).
TEST_P(ShaderLibraryTest, AKernelOnlyInDxbcLoadsOnEveryD3D12Device) {
    if (GetParam() != rhi::Api::D3D12) {
        GTEST_SKIP() << "DXBC is for D3D12 only";
    }
    const auto built = shaders().directory() / "rhi_tests" / "chain_seed.dxbc";
    if (!std::filesystem::is_regular_file(built)) {
        GTEST_SKIP() << "the build made no DXBC (no vkd3d-compiler: .ci/install-dxbc-tools.sh)";
    }
    const KernelFolder folder;
    std::filesystem::copy_file(built, folder.path() / "seed.dxbc");
    rhi::ShaderLibrary library(device(), folder.path());
    EXPECT_EQ(library.unavailableReason("seed"), "");
    EXPECT_NE(library.get("seed"), nullptr);
}

LUMINA_INSTANTIATE_GPU_TEST(ShaderLibraryTest);

} // namespace
} // namespace lumina::test
