// Each higher lumen preset is at least as accurate as the one below it (docs/gi_tests.md): per
// scene, low, medium and high rendered until converged at 128 x 128 and measured against the
// stored references (stored_reference.h); relMSE may not rise from one preset to the next by more
// than the run-to-run spread. Three renders a scene, the high preset's 4096^2 atlas among them:
// minutes each on lavapipe, so label `long`.
#include "tests/frame/stored_reference.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <array>
#include <string>

namespace lumina::test {
namespace {

class FramePresetsGpu : public GpuTestFixture,
                        public ::testing::WithParamInterface<std::tuple<rhi::Api, const char*>> {
protected:
    void SetUp() override { openDevice(std::get<0>(GetParam())); }
};

// relMSE differences below this fraction of the lower preset's are within the run-to-run spread
// of the radiosity's rotated rays and the two-room references' own noise.
constexpr double kPresetSlack = 0.05;

TEST_P(FramePresetsGpu, EachHigherPresetIsAtLeastAsAccurate) {
    LUMINA_REQUIRE_KERNELS();
    const std::string scene = std::get<1>(GetParam());
    const std::array<const char*, 3> presets = {"low", "medium", "high"};
    std::array<StoredReferenceFigures, 3> figures;
    for (size_t i = 0; i < presets.size(); ++i) {
        figures[i] = measureAgainstStoredReference(device(), shaders(), scene, presets[i]);
        ASSERT_TRUE(figures[i].referenceSized) << scene << ": stored reference is not 128x128";
        EXPECT_TRUE(figures[i].converged) << scene << " " << presets[i] << ": not converged";
    }
    for (size_t i = 1; i < presets.size(); ++i) {
        EXPECT_LE(figures[i].lumenRelMse, (1.0 + kPresetSlack) * figures[i - 1].lumenRelMse)
            << scene << ": " << presets[i] << " less accurate than " << presets[i - 1];
    }
}

std::string presetsName(const ::testing::TestParamInfo<std::tuple<rhi::Api, const char*>>& info) {
    return std::string(rhi::apiName(std::get<0>(info.param))) + "_" + poseName(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(Scenes, FramePresetsGpu,
                         ::testing::Combine(::testing::ValuesIn(app::compiledApis()),
                                            ::testing::Values("cornell_box", "cornell_box_point",
                                                              "open_top_box", "two_rooms", "sunlit_rooms",
                                                              "door@240")),
                         presetsName);

} // namespace
} // namespace lumina::test
