// The CPU halves of the bench: checkpoint schedule, convergence rule, reference cache keys, the
// indirect term of the real-time techniques.
#include "gi/bench/reference_cache.h"
#include "gi/bench/technique_runs.h"
#include "gi/frame/gi_technique.h"
#include "gi/frame/indirect_term.h"
#include "gi/scene/scene_loader.h"

#include <gtest/gtest.h>
#include <stdexcept>

namespace lumina::gi {
namespace {

TEST(BenchCheckpoints, PowersOfTwoThenTheLastFrame) {
    EXPECT_EQ(checkpointFrames(1), (std::vector<uint32_t>{1}));
    EXPECT_EQ(checkpointFrames(5), (std::vector<uint32_t>{1, 2, 4, 5}));
    EXPECT_EQ(checkpointFrames(16), (std::vector<uint32_t>{1, 2, 4, 8, 16}));
}

TEST(BenchCheckpoints, ConvergesAtTheFirstCheckpointNearTheLast) {
    const std::vector<Checkpoint> falling = {{1, 1.0}, {2, 0.5}, {4, 0.26}, {8, 0.251}, {16, 0.25}};
    EXPECT_EQ(framesToConverge(falling), 4u); // 0.26 is within 5% of 0.25, 0.5 is not
    const std::vector<Checkpoint> flat = {{1, 0.1}, {2, 0.1}};
    EXPECT_EQ(framesToConverge(flat), 1u);
    EXPECT_EQ(framesToConverge({}), 0u);
}

TEST(ReferenceCache, KeyFollowsEverythingThatChangesTheImage) {
    const scene::Scene scene = scene::loadScene("cornell_box_point");
    const ReferenceRequest request{.width = 32, .height = 32, .spp = 16};
    const uint64_t key = referenceKey(scene, request);
    EXPECT_EQ(key, referenceKey(scene::loadScene("cornell_box_point"), request)) << "not deterministic";

    ReferenceRequest other = request;
    other.spp = 32;
    EXPECT_NE(key, referenceKey(scene, other));
    other = request;
    other.width = 33;
    EXPECT_NE(key, referenceKey(scene, other));
    other = request;
    other.seed += 1;
    EXPECT_NE(key, referenceKey(scene, other));

    scene::Scene brighter = scene;
    brighter.lights.at(0).intensity *= 2.0f;
    EXPECT_NE(key, referenceKey(brighter, request));
    scene::Scene moved = scene;
    moved.camera.position.x += 1.0f;
    EXPECT_NE(key, referenceKey(moved, request));
    scene::Scene recoloured = scene;
    recoloured.materials.at(0).baseColor.r *= 0.5f;
    EXPECT_NE(key, referenceKey(recoloured, request));

    const std::filesystem::path path = referencePath("/cache", scene, request);
    EXPECT_EQ(path.parent_path(), std::filesystem::path("/cache"));
    EXPECT_TRUE(path.filename().string().starts_with("cornell_box_point_32x32_16spp_")) << path;
}

TEST(BenchPresets, UnknownPresetsAreNamed) {
    EXPECT_EQ(findPreset("high").sunShadowSize, 4096u);
    EXPECT_LT(findPreset("low").pointShadowSize, findPreset("medium").pointShadowSize);
    try {
        findPreset("ultra");
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("ultra"), std::string::npos);
    }
}

TEST(BenchIndirect, IsWhatTheCompositeAdds) {
    // scale x E x albedo per channel, as shaders/deferred/composite.hlsl adds it.
    image::Image irradiance = image::Image::rgb(2, 1);
    image::Image albedo = image::Image::rgba(2, 1);
    irradiance.channel("R")[0] = 3.0f;
    irradiance.channel("G")[1] = 2.0f;
    irradiance.channel("B")[1] = 5.0f;
    albedo.channel("R")[0] = 0.5f;
    albedo.channel("G")[1] = 0.25f;
    albedo.channel("B")[1] = 0.0f;
    const image::Image radiance = indirectRadiance(irradiance, albedo, 0.5f);
    EXPECT_EQ(radiance.channelNames(), (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_FLOAT_EQ(radiance.at("R", 0, 0), 0.75f);
    EXPECT_FLOAT_EQ(radiance.at("G", 1, 0), 0.25f);
    EXPECT_EQ(radiance.at("B", 1, 0), 0.0f) << "black albedo reflects nothing";
    EXPECT_EQ(radiance.at("G", 0, 0), 0.0f);
    EXPECT_THROW(indirectRadiance(irradiance, image::Image::rgb(1, 2), 1.0f), image::ImageError);
}

TEST(Presets, GetDearerFromLowToHigh) {
    // One table: render, bench and the viewer read the same shadow maps and GI settings.
    const std::vector<std::string> names = presetNames();
    ASSERT_EQ(names, (std::vector<std::string>{"low", "medium", "high"}));
    for (size_t i = 1; i < names.size(); ++i) {
        const Preset& cheaper = findPreset(names[i - 1]);
        const Preset& dearer = findPreset(names[i]);
        EXPECT_LE(cheaper.sunShadowSize, dearer.sunShadowSize) << names[i];
        EXPECT_LE(cheaper.atlasSize, dearer.atlasSize) << names[i];
        EXPECT_LT(cheaper.cardTexelsAcross, dearer.cardTexelsAcross) << names[i];
        EXPECT_LT(cheaper.radiosityTexelsPerFrame, dearer.radiosityTexelsPerFrame) << names[i];
        EXPECT_GT(cheaper.radiosityTolerance, dearer.radiosityTolerance) << names[i];
        EXPECT_GE(cheaper.probeSpacing, dearer.probeSpacing) << names[i];
        EXPECT_LT(cheaper.raysPerProbe, dearer.raysPerProbe) << names[i];
        EXPECT_LT(cheaper.shGridProbesPerAxis, dearer.shGridProbesPerAxis) << names[i];
        EXPECT_LT(cheaper.shGridFaceSize, dearer.shGridFaceSize) << names[i];
        EXPECT_LT(cheaper.shGridProbesPerFrame, dearer.shGridProbesPerFrame) << names[i];
    }
}

TEST(Presets, FinerGlobalSdfKeepsTheRadiosityLiftsWorldSize) {
    // The radiosity's rays start one voxel of the presets' 64-voxel global SDF off their texel,
    // whatever the resolution (docs/gi.md energy 48.): a lift of a finer grid's own voxel started
    // them inside the open surfaces' shells.
    const scene::Scene scene = scene::loadScene("sunlit_rooms");
    GiSceneSettings settings = giScenePreset(findPreset("medium"), scene);
    EXPECT_EQ(settings.sdf.globalResolution, kPresetGlobalSdfResolution);
    EXPECT_EQ(settings.lighting.trace.originOffsetVoxels, 1.0f);
    setGlobalSdfResolution(settings, 128);
    EXPECT_EQ(settings.sdf.globalResolution, 128u);
    EXPECT_EQ(settings.lighting.trace.originOffsetVoxels, 2.0f);
    EXPECT_THROW(setGlobalSdfResolution(settings, 8), std::invalid_argument);

    const float extent = giSceneExtent(scene);
    setMeshSdfResolution(settings, 128, scene);
    EXPECT_EQ(settings.sdf.mesh.resolution, 128u);
    EXPECT_FLOAT_EQ(settings.cache.minPaddingUnits, extent / 128.0f); // a mesh voxel of the whole scene
    EXPECT_THROW(setMeshSdfResolution(settings, 1000, scene), std::invalid_argument);
}

TEST(ReferenceCache, RgbOfNamesAMissingChannel) {
    image::Image image = image::Image::rgb(2, 1);
    image.addChannel("indirect.R", 1.0f);
    EXPECT_THROW(rgbOf(image, "indirect"), image::ImageError);
    image.addChannel("indirect.G", 2.0f);
    image.addChannel("indirect.B", 3.0f);
    const image::Image rgb = rgbOf(image, "indirect");
    EXPECT_EQ(rgb.at("B", 1, 0), 3.0f);
}

} // namespace
} // namespace lumina::gi
