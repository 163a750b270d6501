#include "gi/bench/change_response.h"

#include "gi/core/frame_context.h"
#include "gi/core/timing_table.h"
#include "gi/deferred/buffer_readback.h"
#include "gi/frame/frame_renderer.h"
#include "gi/frame/preset.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/measure/metrics.h"
#include "gi/scene/scene_animation.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace lumina::gi {

namespace {

// Frames a converged renderer keeps running after its surface cache settled, so the screen
// probes' temporal filters settle too (as `lumina render` does).
constexpr uint32_t kSettleFrames = 32;

FrameRendererSettings settingsFor(const scene::Scene& scene, GiTechnique technique, const std::string& preset,
                                  const ChangeResponseRequest& request) {
    return presetRendererSettings(technique, findPreset(preset), scene, request.width, request.height);
}

// One frame through `renderer`, submitted and waited for; returns its GPU milliseconds.
double renderFrame(rhi::IDevice& device, PipelineCache& pipelines, rhi::ICommandList& list,
                   FrameRenderer& renderer, uint32_t frameIndex) {
    list.begin();
    FrameContext frame(pipelines, list, frameIndex);
    renderer.render(frame);
    list.end();
    rhi::IQueue& queue = device.queue(rhi::QueueType::Graphics);
    queue.waitForValue(queue.submit(list));
    double ms = 0.0;
    for (const rhi::TimerResult& timer : list.timerResults()) {
        ms += timer.milliseconds;
    }
    return ms;
}

image::Image hdrOf(rhi::IDevice& device, const FrameRenderer& renderer) {
    image::Image image = readTextureImage(device, *renderer.deferred().hdr());
    image.removeChannel("A");
    return image;
}

} // namespace

ChangeResponse measureChangeResponse(rhi::IDevice& device, PipelineCache& pipelines,
                                     const scene::Scene& scene, GiTechnique technique,
                                     const std::string& preset, const ChangeResponseRequest& request) {
    if (scene.animation.empty()) {
        throw std::invalid_argument("change response: scene '" + scene.name + "' has no animation");
    }
    if (request.width == 0 || request.height == 0 || request.changeFrames == 0) {
        throw std::invalid_argument("change response: the size and the frames of change must not be zero");
    }
    ChangeResponse result{.scene = scene.name,
                          .technique = giTechniqueName(technique),
                          .preset = preset,
                          .width = request.width,
                          .height = request.height,
                          .changeFrames = request.changeFrames,
                          .relMseAfter = {},
                          .framesToRecover = std::nullopt};
    rhi::CommandListHandle list = device.createCommandList();

    // Fresh renderers built at a pose and run until their surface cache settled: at the held pose
    // (the reference) and at the first (what the change replaced).
    const auto converged = [&](uint64_t poseFrame, std::vector<double>* staticMs) {
        scene::Scene posed = scene;
        scene::animateScene(posed, poseFrame);
        GpuScene gpuScene(device, posed);
        FrameRenderer fresh(device, posed, gpuScene, settingsFor(posed, technique, preset, request));
        std::optional<uint32_t> settledAt;
        for (uint32_t f = 0; f < request.maxReferenceFrames; ++f) {
            const double ms = renderFrame(device, pipelines, *list, fresh, f);
            if (!settledAt && (fresh.gi() == nullptr || fresh.gi()->converged())) {
                settledAt = f;
            } else if (settledAt && staticMs) {
                staticMs->push_back(ms);
            }
            if (staticMs) {
                result.referenceFrames = f + 1;
            }
            if (settledAt && f >= *settledAt + kSettleFrames) {
                break;
            }
        }
        return hdrOf(device, fresh);
    };
    std::vector<double> staticMs;
    const image::Image reference = converged(request.changeFrames - 1, &staticMs);
    result.staticFrameMs = median(staticMs);
    const image::Image before = converged(0, nullptr);
    // The pixels the change touched: luminance differs by more than a tenth between the poses.
    std::vector<bool> changed(size_t(request.width) * request.height, false);
    const auto luminance = [](const image::Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    size_t changedCount = 0;
    for (uint32_t y = 0; y < request.height; ++y) {
        for (uint32_t x = 0; x < request.width; ++x) {
            const double a = luminance(before.rgbAt(x, y)), b = luminance(reference.rgbAt(x, y));
            if (std::abs(a - b) > 0.1 * std::max(a, b)) {
                changed[size_t(y) * request.width + x] = true;
                ++changedCount;
            }
        }
    }
    result.changedRegionFraction = double(changedCount) / double(changed.size());

    // The renderer under test: the animation plays, then the pose is held.
    GpuScene gpuScene(device, scene);
    FrameRenderer renderer(device, scene, gpuScene, settingsFor(scene, technique, preset, request));
    scene::Scene posed = scene;
    std::vector<double> movingMs;
    for (uint32_t f = 0; f < request.changeFrames; ++f) {
        scene::animateScene(posed, f);
        renderer.applyScene(posed);
        const double ms = renderFrame(device, pipelines, *list, renderer, f);
        if (renderer.lastChanges().any()) {
            movingMs.push_back(ms);
        }
    }
    result.movingFrameMs = median(movingMs);
    const image::Image atStop = hdrOf(device, renderer);
    result.relMseAtStop = measure::relMse(reference, atStop);
    const std::vector<float> perPixel = measure::relMseMap(reference, atStop);
    double changedSum = 0.0;
    size_t changedPixels = 0;
    for (size_t i = 0; i < perPixel.size(); ++i) {
        if (changed[i] && std::isfinite(perPixel[i])) {
            changedSum += perPixel[i];
            ++changedPixels;
        }
    }
    result.changedRegionRelMseAtStop = changedPixels ? changedSum / double(changedPixels) : 0.0;
    uint32_t nextReport = 1;
    for (uint32_t k = 1; k <= request.maxRecoveryFrames; ++k) {
        result.msToRecover += renderFrame(device, pipelines, *list, renderer, request.changeFrames + k - 1);
        const double error = measure::relMse(reference, hdrOf(device, renderer));
        if (k == nextReport) {
            result.relMseAfter.push_back(error);
            nextReport *= 2;
        }
        if (error <= request.tolerance) {
            result.framesToRecover = k;
            break;
        }
    }
    if (!result.framesToRecover) {
        result.msToRecover = 0.0;
    }
    return result;
}

void writeChangeResponseCsv(const std::filesystem::path& path, const std::vector<ChangeResponse>& rows) {
    std::ofstream out(path);
    if (!out) {
        throw std::runtime_error("cannot write " + path.string());
    }
    out << "scene,technique,preset,width,height,change_frames,moving_frame_ms,static_frame_ms,relmse_at_stop,"
           "changed_region_relmse_at_stop,changed_region_fraction,frames_to_recover,ms_to_recover,"
           "relmse_after_1_2_4_8\n";
    for (const ChangeResponse& r : rows) {
        out << r.scene << ',' << r.technique << ',' << r.preset << ',' << r.width << ',' << r.height << ','
            << r.changeFrames << ',' << r.movingFrameMs << ',' << r.staticFrameMs << ',' << r.relMseAtStop
            << ',' << r.changedRegionRelMseAtStop << ',' << r.changedRegionFraction << ','
            << (r.framesToRecover ? std::to_string(*r.framesToRecover) : std::string("not within limit"))
            << ',' << r.msToRecover << ',';
        for (size_t i = 0; i < r.relMseAfter.size(); ++i) {
            out << (i ? " " : "") << r.relMseAfter[i];
        }
        out << '\n';
    }
}

} // namespace lumina::gi
