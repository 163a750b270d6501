#include "tests/frame/stored_reference.h"

#include "gi/image/exr.h"
#include "gi/measure/metrics.h"
#include "gi/scene/scene_animation.h"
#include "gi/scene/scene_loader.h"
#include "tests/frame/frame_harness.h"

#include <cstdio>
#include <optional>
#include <utility>

namespace lumina::test {

namespace {

constexpr uint32_t kSettleFrames = 48; // as `lumina render` without --frames

// a - b, channel by channel (R, G, B).
image::Image difference(const image::Image& a, const image::Image& b) {
    image::Image out = image::Image::rgb(a.width(), a.height());
    for (const char* c : {"R", "G", "B"}) {
        const auto x = a.channel(c);
        const auto y = b.channel(c);
        auto o = out.channel(c);
        for (size_t i = 0; i < o.size(); ++i) {
            o[i] = x[i] - y[i];
        }
    }
    return out;
}

// Mean radiance over R, G and B.
double meanRadiance(const image::Image& image) {
    double sum = 0.0;
    for (const char* c : {"R", "G", "B"}) {
        for (const float v : image.channel(c)) {
            sum += v;
        }
    }
    return sum / (3.0 * double(image.pixelCount()));
}

// The scene's name and the animation frame "<scene>@F" poses it at, if any.
struct ScenePose {
    std::string scene;
    std::optional<uint32_t> frame;
};

ScenePose splitPose(const std::string& name) {
    const size_t at = name.find('@');
    if (at == std::string::npos) {
        return {name, std::nullopt};
    }
    return {name.substr(0, at), uint32_t(std::stoul(name.substr(at + 1)))};
}

} // namespace

std::string poseName(const std::string& scene) {
    const ScenePose pose = splitPose(scene);
    return pose.frame ? pose.scene + "_frame" + std::to_string(*pose.frame) : pose.scene;
}

std::filesystem::path storedReferencePath(const std::string& scene) {
    const std::string file = scene == "cornell_box_moving" ? "cornell_box" : poseName(scene);
    return std::filesystem::path(LUMINA_FRAME_TEST_DATA_DIR) / (file + "_128x128.exr");
}

StoredReferenceFigures measureAgainstStoredReference(rhi::IDevice& device, rhi::ShaderLibrary& shaders,
                                                     const std::string& scene, const std::string& preset) {
    const image::Image reference = rgbOnly(image::readExr(storedReferencePath(scene)));
    StoredReferenceFigures f;
    f.referenceSized =
        reference.width() == kStoredReferenceSize && reference.height() == kStoredReferenceSize;
    if (!f.referenceSized) {
        return f;
    }
    const ScenePose pose = splitPose(scene);
    scene::Scene loaded = scene::loadScene(pose.scene);
    if (pose.frame) {
        scene::animateScene(loaded, *pose.frame);
    }
    FrameHarness h(device, shaders, std::move(loaded),
                   {.width = kStoredReferenceSize, .height = kStoredReferenceSize, .preset = preset});
    f.frames = h.renderUntilConverged(kSettleFrames);
    f.converged = h.converged();
    const image::Image lumen = h.hdr();
    const image::Image direct = h.direct();
    f.nonFinitePixels = measure::countNonFinite(lumen).total();
    f.lumenRelMse = measure::relMse(reference, lumen);
    f.directRelMse = measure::relMse(reference, direct);
    f.indirectRelMse = measure::relMse(difference(reference, direct), difference(lumen, direct));
    f.meanRatio = meanRadiance(lumen) / meanRadiance(reference);
    std::printf("%s %ux%u %s: %u frames; relMSE lumen %.5f, direct only %.5f (lumen / direct %.3f), indirect "
                "term %.5f; mean radiance lumen / reference %.4f\n",
                scene.c_str(), kStoredReferenceSize, kStoredReferenceSize, preset.c_str(), f.frames,
                f.lumenRelMse, f.directRelMse, f.lumenRelMse / f.directRelMse, f.indirectRelMse, f.meanRatio);
    return f;
}

} // namespace lumina::test
