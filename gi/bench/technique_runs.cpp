#include "gi/bench/technique_runs.h"

#include "gi/core/frame_context.h"
#include "gi/deferred/buffer_readback.h"
#include "gi/frame/frame_renderer.h"
#include "gi/frame/indirect_term.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/measure/compare.h"
#include "gi/measure/metrics.h"
#include "gi/pathtracer/path_tracer.h"
#include "gi/pathtracer/path_tracer_scene.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>

namespace lumina::gi {

namespace {

// Samples in each timed batch of pathTracerMsPerSample (three, after one warm-up sample).
constexpr uint32_t kCalibrationSamples = 4;

// Measures one checkpoint: the final image and the indirect term against the reference.
Checkpoint measure(uint32_t frame, const image::Image& finalImage, const image::Image& indirect,
                   const Reference& reference, uint64_t& nonFinite) {
    const image::Image referenceIndirect = rgbOf(reference.image, "indirect");
    const measure::CompareResult final = measure::compareImages(reference.image, finalImage);
    nonFinite += final.test.total() + measure::countNonFinite(indirect).total();
    return {.frame = frame,
            .relMse = final.linear.relMse,
            .indirectRelMse = measure::relMse(referenceIndirect, indirect),
            .flip = final.flip.mean};
}

image::Image rgbOnly(image::Image image) {
    image.removeChannel("A");
    return image;
}

// How runFrames drives a technique.
struct FrameHooks {
    std::function<void(FrameContext&)> record;
    std::function<std::pair<image::Image, image::Image>()> readImages; // final image, indirect term
    std::function<bool()> settled; // after a frame: its per-frame work has stopped changing
};

// Runs `frames` frames, timing each (all of them, and apart those after the technique settled),
// and measures the checkpoints.
void runFrames(rhi::IDevice& device, PipelineCache& pipelines, const RunRequest& request,
               const Reference& reference, const FrameHooks& hooks, TechniqueRun& run) {
    TimingTable table;
    TimingTable settledTable;
    rhi::CommandListHandle list = device.createCommandList();
    rhi::IQueue& queue = device.queue(rhi::QueueType::Graphics);
    const std::vector<uint32_t> checkpoints = checkpointFrames(request.frames);
    for (uint32_t frameIndex = 0; frameIndex < request.frames; ++frameIndex) {
        list->begin();
        FrameContext frame(pipelines, *list, frameIndex);
        frame.setForcedPasses(&request.forcedPasses);
        hooks.record(frame);
        list->end();
        queue.waitForValue(queue.submit(*list));
        table.addFrame(list->timerResults(), frame.skipped());
        if (run.settledAfterFrame) {
            settledTable.addFrame(list->timerResults(), frame.skipped());
        } else if (hooks.settled()) {
            run.settledAfterFrame = frameIndex + 1;
        }
        if (std::ranges::find(checkpoints, frameIndex + 1) != checkpoints.end()) {
            auto [finalImage, indirect] = hooks.readImages();
            run.checkpoints.push_back(
                measure(frameIndex + 1, finalImage, indirect, reference, run.nonFinitePixels));
            if (frameIndex + 1 == request.frames) {
                run.finalImage = std::move(finalImage);
            }
        }
    }
    run.frames = request.frames;
    run.frameMs = table.medianFrameMs();
    run.frameMsEach = table.frameTotals();
    run.passes = table.passes();
    run.skips = table.skips();
    if (settledTable.recordedFrames() != 0) {
        run.settledFrameMs = settledTable.medianFrameMs();
        run.settledPasses = settledTable.passes();
    }
    run.framesToConverge = framesToConverge(run.checkpoints);
}

void checkRequest(const RunRequest& request, const Reference& reference) {
    if (request.frames == 0) {
        throw std::invalid_argument("bench: at least one frame per run");
    }
    if (reference.image.width() != request.width || reference.image.height() != request.height) {
        throw std::invalid_argument("bench: the reference is " + std::to_string(reference.image.width()) +
                                    "x" + std::to_string(reference.image.height()) + ", the run " +
                                    std::to_string(request.width) + "x" + std::to_string(request.height));
    }
}

} // namespace

std::vector<uint32_t> checkpointFrames(uint32_t frames) {
    std::vector<uint32_t> result;
    for (uint32_t f = 1; f < frames; f *= 2) {
        result.push_back(f);
    }
    result.push_back(frames);
    return result;
}

uint32_t framesToConverge(const std::vector<Checkpoint>& checkpoints, double tolerance) {
    if (checkpoints.empty()) {
        return 0;
    }
    const double last = checkpoints.back().relMse;
    for (const Checkpoint& c : checkpoints) {
        if (std::abs(c.relMse - last) <= tolerance * last) {
            return c.frame;
        }
    }
    return checkpoints.back().frame;
}

TechniqueRun runRealTime(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                         GiTechnique technique, const std::string& preset, const RunRequest& request,
                         const Reference& reference) {
    checkRequest(request, reference);
    FrameRendererSettings settings =
        presetRendererSettings(technique, findPreset(preset), scene, request.width, request.height);
    TechniqueRun run{.technique = giTechniqueName(technique),
                     .preset = preset,
                     .width = request.width,
                     .height = request.height};
    const uint64_t baseline = device.allocatedMemoryBytes();
    GpuScene gpuScene(device, scene);
    FrameRenderer renderer(device, scene, gpuScene, std::move(settings));
    runFrames(device, pipelines, request, reference,
              {.record = [&](FrameContext& frame) { renderer.render(frame); },
               .readImages =
                   [&] {
                       return std::pair{rgbOnly(readTextureImage(device, *renderer.deferred().hdr())),
                                        readIndirectRadiance(device, renderer)};
                   },
               // The surface cache stops its radiosity once converged; the direct renderer
               // draws its shadow maps in the first frame only.
               .settled = [&] { return renderer.gi() == nullptr || renderer.gi()->converged(); }},
              run);
    run.gpuMemoryBytes = device.allocatedMemoryBytes() - baseline;
    return run;
}

TechniqueRun runPathTracer(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                           const std::string& preset, const RunRequest& request, const Reference& reference) {
    checkRequest(request, reference);
    if (request.seed == ReferenceRequest{}.seed) {
        throw std::invalid_argument("bench: the path tracer under test must not use the reference's seed");
    }
    TechniqueRun run{.technique = "pathtracer",
                     .preset = preset,
                     .width = request.width,
                     .height = request.height,
                     .samplesPerFrame = std::max(request.samplesPerFrame, 1u)};
    const uint64_t baseline = device.allocatedMemoryBytes();
    const PathTracerScene traced(device, scene);
    PathTracer tracer(device, traced, scene,
                      {.width = request.width, .height = request.height, .seed = request.seed, .aovs = true});
    runFrames(device, pipelines, request, reference,
              {.record = [&](FrameContext& frame) { tracer.recordSamples(frame, run.samplesPerFrame); },
               .readImages =
                   [&] {
                       const PathTracerResult result = tracer.readResult();
                       image::Image radiance = image::Image::rgb(request.width, request.height);
                       for (const char* c : {"R", "G", "B"}) {
                           std::ranges::copy(result.image.channel(c), radiance.channel(c).begin());
                       }
                       return std::pair{std::move(radiance), rgbOf(result.image, "indirect")};
                   },
               // Every frame does the same work.
               .settled = [] { return true; }},
              run);
    run.gpuMemoryBytes = device.allocatedMemoryBytes() - baseline;
    return run;
}

double pathTracerMsPerSample(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                             uint32_t width, uint32_t height) {
    const PathTracerScene traced(device, scene);
    PathTracer tracer(device, traced, scene, {.width = width, .height = height, .seed = 7, .aovs = true});
    rhi::CommandListHandle list = device.createCommandList();
    rhi::IQueue& queue = device.queue(rhi::QueueType::Graphics);
    // The first submission also compiles the kernel on some drivers; the others are timed as
    // the bench's frames are: several samples in one list (lavapipe runs dispatches
    // asynchronously, so a lone dispatch's timestamps say little). The fastest of three: on the
    // H200 one batch right after the references read 17.5 ms a sample of `city` at 1080p, where
    // the runs' frames then took 4.9 ms for one sample.
    double fastest = std::numeric_limits<double>::infinity();
    for (uint32_t batch = 0; batch < 4; ++batch) {
        const uint32_t samples = batch == 0 ? 1u : kCalibrationSamples;
        list->begin();
        FrameContext frame(pipelines, *list, samples);
        tracer.recordSamples(frame, samples);
        list->end();
        queue.waitForValue(queue.submit(*list));
        double ms = 0.0;
        for (const rhi::TimerResult& timer : list->timerResults()) {
            ms += timer.milliseconds;
        }
        if (batch > 0) {
            fastest = std::min(fastest, ms);
        }
    }
    return fastest / kCalibrationSamples;
}

} // namespace lumina::gi
