// Goldens of a scene's SDFs (docs/goldens.md), for cornell_box and atrium: a z slice of the
// global SDF (distance normalised to [0, 1] over [-maxDistance, maxDistance]) and 64x64 normal
// views from the scene camera traced through the near field (per-mesh SDFs) and the far field
// (global SDF). Mesh SDFs at 32 voxels and no cache, so that the test builds everything and
// stays fast on lavapipe (atrium: about 0.2 s of SDF builds). Regenerate with
//   LUMINA_UPDATE_GOLDENS=1 ctest -L golden      (Debian 12's lavapipe only)
#include "gi/core/pipeline_cache.h"
#include "gi/scene/scene_loader.h"
#include "gi/sdf/sdf_views.h"
#include "tests/golden/golden.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <iostream>
#include <tuple>

namespace lumina::test {
namespace {

constexpr uint32_t kViewSize = 64;
constexpr uint32_t kMeshResolution = 32;
// Normalised distances: the GPU's trilinear weights move values by thousandths of a voxel.
constexpr GoldenTolerance kSlice{.meanAbsError = 0.002, .percentile = 0.99, .percentileError = 0.02};
// Normal colours (0.5 * n + 0.5, black on a miss): silhouette pixels may resolve either way
// on another driver, within the last 1%.
constexpr GoldenTolerance kNormals{.meanAbsError = 0.004, .percentile = 0.99, .percentileError = 0.04};

class SdfGoldenTest : public GpuTestFixture,
                      public ::testing::WithParamInterface<std::tuple<rhi::Api, std::string>> {
protected:
    void SetUp() override { openDevice(std::get<0>(GetParam())); }
};

// Grey (EXR files hold R, G and B): 0 at -maxDistance, 0.5 on surfaces, 1 at maxDistance; +y up.
image::Image normalisedSlice(const sdf::GlobalSdf& grid, uint32_t z, float maxDistance) {
    image::Image out = image::Image::rgb(grid.dims.x, grid.dims.y);
    for (uint32_t row = 0; row < grid.dims.y; ++row) {
        for (uint32_t x = 0; x < grid.dims.x; ++x) {
            const float v =
                0.5f + 0.5f * grid.distances[grid.voxelIndex(x, grid.dims.y - 1 - row, z)] / maxDistance;
            out.setRgb(x, row, {v, v, v});
        }
    }
    return out;
}

TEST_P(SdfGoldenTest, GlobalSliceAndNormalViewsMatchTheirGoldens) {
    const std::string name = std::get<1>(GetParam());
    const scene::Scene scene = scene::loadScene(name);
    sdf::SceneSdfSettings settings;
    settings.mesh.resolution = kMeshResolution;
    settings.useCache = false;
    gi::PipelineCache pipelines(device(), shaders());
    {
        sdf::SceneSdf sdfs(device(), sdf::buildSceneSdfData(scene, settings));
        sdf::SdfCameraTracer near(device(), kViewSize, kViewSize);
        sdf::SdfCameraTracer far(device(), kViewSize, kViewSize);
        rhi::CommandListHandle list = device().createCommandList();
        list->begin();
        gi::FrameContext frame(pipelines, *list, 0);
        sdfs.record(frame);
        const float maxDistance = scene.camera.farPlane;
        near.record(frame, sdfs, scene.camera, sdf::SdfField::Near,
                    sdf::defaultTraceParams(sdf::SdfField::Near, maxDistance), "sdf golden: near field");
        far.record(frame, sdfs, scene.camera, sdf::SdfField::Far,
                   sdf::defaultTraceParams(sdf::SdfField::Far, maxDistance), "sdf golden: far field");
        list->end();
        submitAndWait(*list);

        const sdf::GlobalSdf global = sdf::readGlobalSdf(device(), sdfs);
        image::Image nearView = near.readNormals(device());
        image::Image farView = far.readNormals(device());
        nearView.removeChannel("t");
        farView.removeChannel("t");
        const std::vector<std::pair<GoldenSpec, image::Image>> checks = {
            {{.name = "sdf_" + name + "_global_slice", .tolerance = kSlice},
             normalisedSlice(global, global.dims.z / 2, sdfs.data().global.maxDistance)},
            {{.name = "sdf_" + name + "_near_normals", .tolerance = kNormals}, nearView},
            {{.name = "sdf_" + name + "_far_normals", .tolerance = kNormals}, farView},
        };
        for (const auto& [golden, image] : checks) {
            const GoldenResult result = checkGolden(golden, image, device().adapter());
            EXPECT_TRUE(result.passed) << result.message;
            std::cout << result.message << '\n';
        }
    }
}

std::string goldenTestName(const ::testing::TestParamInfo<std::tuple<rhi::Api, std::string>>& info) {
    return std::string(rhi::apiName(std::get<0>(info.param))) + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SdfGoldenTest,
                         ::testing::Combine(::testing::ValuesIn(app::compiledApis()),
                                            ::testing::Values(std::string("cornell_box"),
                                                              std::string("atrium"))),
                         goldenTestName);

} // namespace
} // namespace lumina::test
