// `lumina reference SCENE`: the path-traced ground truth every accuracy figure is measured
// against (gi/pathtracer/, docs/pathtracer.md). Renders progressively in short submissions,
// shows progress on stderr, stops at --spp or at --target-error, writes an EXR of linear
// radiance, per-pixel variance and optional AOVs, and prints samples/s and rays/s.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#ifdef _WIN32
#include <io.h>
#define LUMINA_ISATTY _isatty
#define LUMINA_FILENO _fileno
#else
#include <unistd.h>
#define LUMINA_ISATTY isatty
#define LUMINA_FILENO fileno
#endif

#include "app/command.h"
#include "app/commands/scene_options.h"
#include "app/commands/shard_option.h"
#include "gi/bench/reference_cache.h"
#include "gi/bench/reference_shards.h"
#include "gi/core/build_info.h"
#include "gi/core/frame_context.h"
#include "gi/core/pipeline_cache.h"
#include "gi/image/exr.h"
#include "gi/image/png.h"
#include "gi/pathtracer/path_tracer.h"
#include "gi/pathtracer/path_tracer_scene.h"
#include "gi/scene/scene_loader.h"

namespace lumina::app {

namespace {

using Clock = std::chrono::steady_clock;

constexpr uint32_t kDefaultSpp = 256;
constexpr uint32_t kTargetErrorMaxSpp = 1u << 16; // the cap with --target-error and no --spp
constexpr uint32_t kMinSamplesForTarget = 16;     // fewer give too rough a variance estimate
constexpr double kSubmissionSeconds = 0.5;        // aim for submissions this long
constexpr uint32_t kMaxSamplesPerSubmission = 64;
constexpr double kTargetCheckSeconds = 2.0; // read the variance back at most this often
constexpr int kBarWidth = 30;

double seconds(Clock::duration d) {
    return std::chrono::duration<double>(d).count();
}

std::string formatDuration(double s) {
    char text[32];
    if (!std::isfinite(s)) {
        return "?";
    }
    if (s < 60.0) {
        std::snprintf(text, sizeof(text), "%.1fs", s);
    } else if (s < 3600.0) {
        std::snprintf(text, sizeof(text), "%dm%02ds", int(s) / 60, int(s) % 60);
    } else {
        std::snprintf(text, sizeof(text), "%dh%02dm", int(s) / 3600, int(s) / 60 % 60);
    }
    return text;
}

// One line on stderr, redrawn in place on a terminal, every 10% otherwise.
class ProgressBar {
public:
    ProgressBar() : tty_(LUMINA_ISATTY(LUMINA_FILENO(stderr)) != 0) {}

    // `total`: the samples expected in the end (the --spp cap, or the estimate of what
    // --target-error needs).
    void update(uint32_t done, uint32_t total, double elapsed, const std::string& extra) {
        total_ = std::max(total, done);
        const double fraction = total_ ? double(done) / total_ : 1.0;
        const int decile = int(fraction * 10.0);
        if (!tty_ && decile == lastDecile_ && done < total_) {
            return;
        }
        lastDecile_ = decile;
        const double eta = done ? elapsed * (double(total_) - done) / done : NAN;
        const int filled = int(fraction * kBarWidth);
        std::string bar(size_t(filled), '#');
        bar.resize(kBarWidth, '.');
        std::fprintf(stderr, "%s[%s] %u/%u spp, %s elapsed, ETA %s%s%s", tty_ ? "\r" : "", bar.c_str(), done,
                     total_, formatDuration(elapsed).c_str(), formatDuration(eta).c_str(), extra.c_str(),
                     tty_ ? "   " : "\n");
        std::fflush(stderr);
    }
    void finish() {
        if (tty_) {
            std::fprintf(stderr, "\n");
        }
    }

private:
    uint32_t total_ = 0;
    bool tty_;
    int lastDecile_ = -1;
};

int runReference(const ParsedArgs& args) {
    if (args.positional.size() != 1) {
        throw UsageError(
            "reference takes one scene: a built-in name or a .json, .gltf or .glb path (see lumina "
            "reference --help)");
    }
    const bool hasTarget = args.has("target-error");
    const double targetError = hasTarget ? args.getDouble("target-error", 0.0) : 0.0;
    if (hasTarget && !(targetError > 0.0 && std::isfinite(targetError))) {
        throw UsageError("--target-error: must be a positive number, got " + args.get("target-error"));
    }
    const auto spp = uint32_t(args.getUint("spp", hasTarget ? kTargetErrorMaxSpp : kDefaultSpp, 1, 1u << 24));
    gi::PathTracerSettings settings;
    settings.maxBounces = uint32_t(args.getUint("max-bounces", settings.maxBounces, 0, 1u << 16));
    if (args.common.seed > UINT32_MAX) {
        throw UsageError("--seed: at most " + std::to_string(UINT32_MAX));
    }
    settings.seed = uint32_t(args.common.seed);
    settings.aovs = args.has("aovs");
    settings.jitter = !args.has("pixel-centres");

    const std::optional<gi::Shard> shard = parseShardFlag(args);
    if (shard && hasTarget) {
        throw UsageError(
            "--shard with --target-error: the shards would stop at different sample counts; give "
            "--spp");
    }
    if (shard && args.has("png")) {
        throw UsageError(
            "--shard with --png: a shard holds some rows only; lumina merge --png makes the preview");
    }

    const std::string& name = args.positional.front();
    scene::Scene loaded = scene::loadScene(name, sceneLoadOptions(args));
    poseAtAnimationFrame(args, loaded);
    if (args.common.size) {
        settings.width = args.common.size->width;
        settings.height = args.common.size->height;
    }
    if (shard) {
        const uint32_t height = settings.height ? settings.height : loaded.image.height;
        try {
            const gi::RowBand rows = gi::shardRows(height, *shard);
            settings.firstRow = rows.first;
            settings.rowCount = rows.count;
        } catch (const std::invalid_argument& e) {
            throw UsageError("--shard " + shard->text() + ": " + e.what());
        }
    }
    const std::string out = !args.common.out.empty() ? args.common.out
                            : shard ? loaded.name + "_reference_shard" + std::to_string(shard->index) + "of" +
                                          std::to_string(shard->count) + ".exr"
                                    : loaded.name + "_reference.exr";
    // Fail before rendering, not after.
    for (const std::string& path : {out, args.get("png")}) {
        if (path.empty()) {
            continue;
        }
        const std::filesystem::path parent = std::filesystem::absolute(path).parent_path();
        if (!std::filesystem::is_directory(parent)) {
            throw UsageError("cannot write '" + path + "': no directory " + parent.string());
        }
    }

    rhi::DeviceHandle device = openDevice(args.common);
    std::cerr << "device: " << device->adapter().name << " (" << rhi::apiName(device->api()) << ", driver "
              << device->adapter().driver << ")\n";
    rhi::ShaderLibrary shaders(*device);
    gi::PipelineCache pipelines(*device, shaders);
    const gi::PathTracerScene traced(*device, loaded);
    const gi::PathTracerSceneStats& stats = traced.stats();
    gi::PathTracer tracer(*device, traced, loaded, settings);
    const uint32_t width = tracer.settings().width, height = tracer.settings().height;
    const uint32_t tracedRows = tracer.rowCount();
    if (shard) {
        std::cerr << "shard " << shard->text() << ": rows " << settings.firstRow << " to "
                  << settings.firstRow + tracedRows - 1 << " of " << height << "\n";
    }
    std::cerr << "scene: " << loaded.name << ", " << stats.triangles << " triangles, " << stats.emitters
              << " emissive, " << stats.lights << " punctual lights; BVH " << stats.bvhNodes
              << " nodes, depth " << stats.bvhDepth << ", built in " << formatDuration(stats.buildSeconds)
              << "\n"
              << "rendering " << width << "x" << height << ", up to " << spp << " spp, max bounces "
              << settings.maxBounces << ", seed " << settings.seed
              << (hasTarget ? ", stopping at relative standard error " + std::to_string(targetError) : "")
              << "\n";

    rhi::CommandListHandle list = device->createCommandList();
    rhi::IQueue& queue = device->queue(rhi::QueueType::Graphics);
    ProgressBar progress;
    uint32_t expected = spp; // samples the render is expected to take
    const Clock::time_point start = Clock::now();
    Clock::time_point lastCheck = start;
    double gpuMs = 0.0, error = INFINITY;
    // The first submission also compiles the kernel on some drivers (lavapipe does so at the
    // first dispatch): throughput is measured over the others.
    double firstSeconds = 0.0;
    uint32_t firstSamples = 0;
    uint32_t batch = 1;
    uint64_t frame = 0;
    while (tracer.samples() < spp) {
        uint32_t count = std::min(batch, spp - tracer.samples());
        if (hasTarget && tracer.samples() < kMinSamplesForTarget) {
            count = std::min(count, kMinSamplesForTarget - tracer.samples()); // the first estimate, on time
        }
        const Clock::time_point batchStart = Clock::now();
        list->begin();
        gi::FrameContext context(pipelines, *list, frame++);
        tracer.recordSamples(context, count);
        list->end();
        queue.waitForValue(queue.submit(*list));
        for (const rhi::TimerResult& timer : list->timerResults()) {
            gpuMs += timer.milliseconds;
        }
        const double batchSeconds = seconds(Clock::now() - batchStart);
        if (frame == 1) {
            firstSeconds = batchSeconds;
            firstSamples = count;
        }
        const double perSample = batchSeconds / count;
        batch = uint32_t(std::clamp(kSubmissionSeconds / std::max(perSample, 1e-6), 1.0,
                                    double(kMaxSamplesPerSubmission)));

        std::string extra;
        const bool last = tracer.samples() >= spp;
        if (hasTarget && tracer.samples() >= kMinSamplesForTarget &&
            (!std::isfinite(error) || seconds(Clock::now() - lastCheck) >= kTargetCheckSeconds || last ||
             tracer.samples() >= expected)) {
            lastCheck = Clock::now();
            error = tracer.meanRelativeStandardError();
            // The error falls as 1/sqrt(spp): the samples the target needs.
            const double needed = std::ceil(tracer.samples() * (error / targetError) * (error / targetError));
            expected = uint32_t(std::clamp(needed, double(tracer.samples()), double(spp)));
        }
        if (std::isfinite(error)) {
            char text[48];
            std::snprintf(text, sizeof(text), ", rel. std. error %.4g", error);
            extra = text;
        }
        progress.update(tracer.samples(), expected, seconds(Clock::now() - start), extra);
        if (hasTarget && error <= targetError) {
            break;
        }
    }
    progress.finish();
    const double renderSeconds = seconds(Clock::now() - start);

    const gi::PathTracerResult result = tracer.readResult();
    image::writeExr(out, result.image);
    if (shard) {
        gi::writeReferenceShardInfo(out, {.scene = loaded.name,
                                          .sceneDigest = gi::sceneDigest(loaded),
                                          .width = width,
                                          .height = height,
                                          .spp = result.samples,
                                          .seed = settings.seed,
                                          .maxBounces = settings.maxBounces,
                                          .aovs = settings.aovs,
                                          .jitter = settings.jitter,
                                          .commit = std::string(gi::gitCommit()),
                                          .shard = *shard,
                                          .rows = {.first = settings.firstRow, .count = tracedRows}});
    }
    if (args.has("png")) {
        image::writePng(args.get("png"), result.image);
    }
    const double pixels = double(width) * double(tracedRows);
    const double samples = double(result.samples) * pixels;
    const double raysPerSample = double(result.rays) / samples;
    // Steady state: without the first submission when there were others.
    const bool steady = result.samples > firstSamples && renderSeconds > firstSeconds;
    const double rate = steady
                            ? double(result.samples - firstSamples) * pixels / (renderSeconds - firstSeconds)
                            : samples / renderSeconds;
    std::printf("%s: %ux%u, %u spp in %.2f s (GPU %.2f s, first submission %.2f s)\n", loaded.name.c_str(),
                width, height, result.samples, renderSeconds, gpuMs / 1000.0, firstSeconds);
    std::printf("throughput%s: %.4g samples/s, %.4g rays/s (%.2f rays per sample, shadow rays included)\n",
                steady ? " after the first submission" : "", rate, rate * raysPerSample, raysPerSample);
    std::printf("mean relative standard error %.4g\n", result.meanRelativeStandardError);
    if (result.nonFiniteSamples) {
        std::printf("warning: %llu non-finite samples were replaced by 0\n",
                    static_cast<unsigned long long>(result.nonFiniteSamples));
    }
    std::printf("wrote %s%s%s\n", out.c_str(), args.has("png") ? " and " : "",
                shard ? (" and " + gi::shardInfoPath(out).string()).c_str() : args.get("png").c_str());
    if (device->validationMessageCount() != 0) {
        std::cerr << "reference: " << device->validationMessageCount() << " validation message(s)\n";
        return 1;
    }
    return 0;
}

} // namespace

Command referenceCommand() {
    return {
        .name = "reference",
        .summary = "path-trace the ground-truth image of a scene (EXR with variance and AOVs)",
        .usage = "lumina reference SCENE [--spp N] [--target-error E] [--out ref.exr] [--size WxH] [--aovs] "
                 "[--max-bounces N] [--seed N] [--animation-frame F] [--png PATH] [--shard i/n] "
                 "[--no-default-light] [--sky FILE.exr [--sky-intensity K]]",
        .description =
            "Renders SCENE (a built-in name or a scene/glTF path) with the reference path tracer on the GPU: "
            "the same camera, pixel footprint, units and lights as the real-time renderer "
            "(docs/conventions.md). Samples accumulate progressively, one per pixel per dispatch; a progress "
            "bar with the time left goes to stderr. The EXR (default SCENE_reference.exr) holds R, G, B "
            "(linear radiance, float) and variance.R/G/B (the variance of each pixel's mean); --aovs adds "
            "albedo.*, normal.X/Y/Z, direct.* (at most one bounce) and indirect.* (two or more). At the end "
            "it "
            "prints samples/s and rays/s. The same seed gives the same image. With --shard i/n it traces "
            "band i of n equal bands of rows (0-based) and writes only those rows, with OUT.shard.json "
            "beside the EXR saying which run and rows they are; a pixel's random numbers depend on its "
            "place in the whole image, so `lumina merge` stitches the n shards into exactly the file one "
            "run writes (docs/batch.md).",
        .flags = withSceneLoadFlags(
            {{"spp", "N", "samples per pixel (default 256; the cap with --target-error: 65536)"},
             {"target-error", "E",
              "stop once the mean relative standard error of the pixels falls below E (e.g. 0.01)"},
             {"aovs", "", "also write albedo, normal, direct and indirect channels"},
             {"max-bounces", "N", "scattering events per path (default 1024; roulette ends most paths)"},
             {"pixel-centres", "", "sample pixel centres only (no antialiasing), like a rasteriser"},
             {"animation-frame", "F",
              "pose an animated scene at frame F (default: the scene as built, before any animation; "
              "`lumina render --animation-frame F` renders the same pose)"},
             {"png", "PATH", "also write a tonemapped PNG preview"},
             shardFlag("trace band i of n bands of rows only (0 <= i < n; not with --target-error or "
                       "--png; default OUT: SCENE_reference_shardIofN.exr)")}),
        .run = runReference};
}

} // namespace lumina::app
