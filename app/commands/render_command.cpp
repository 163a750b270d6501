// `lumina render SCENE`: the real-time deferred frame (GBuffer, sun and point-light shadows,
// direct light, composite) rendered on the GPU and written as a PNG, optionally with the linear
// HDR result as EXR, every intermediate buffer, and the GPU time of each pass.
#include "app/command.h"
#include "gi/core/build_info.h"
#include "gi/core/frame_context.h"
#include "gi/core/pipeline_cache.h"
#include "gi/core/timing_table.h"
#include "gi/deferred/buffer_readback.h"
#include "gi/deferred/deferred_renderer.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/image/exr.h"
#include "gi/image/png.h"
#include "gi/scene/scene_loader.h"
#include "rhi/rhi.h"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>

namespace lumina::app {

namespace {

// Frames run with --timings and no --frames: enough for a stable median on a real GPU and
// for the skipped shadow passes to show in the table.
constexpr uint32_t kTimingFrames = 60;

int runRender(const ParsedArgs& args) {
    if (args.positional.size() != 1) {
        throw UsageError("render takes one scene: a built-in name or a .json, .gltf or .glb path (see lumina "
                         "render --help)");
    }
    const bool timings = args.has("timings") || args.has("timings-json");
    const uint32_t frames = args.common.frames.value_or(timings ? kTimingFrames : 1u);
    if (frames == 0) {
        throw UsageError("--frames: at least one frame");
    }
    const auto warmup = static_cast<uint32_t>(args.getUint("warmup", 0, 0, frames - 1));
    const auto exposure = static_cast<float>(args.getDouble("exposure", 0.0));

    scene::Scene loaded = scene::loadScene(args.positional.front());
    if (args.common.size) {
        loaded.image = {args.common.size->width, args.common.size->height};
    }
    const std::filesystem::path out = args.common.out.empty() ? loaded.name + ".png" : args.common.out;

    rhi::DeviceHandle device = openDevice(args.common);
    std::cout << "device: " << device->adapter().name << " (" << rhi::apiName(device->api()) << ", driver "
              << device->adapter().driver << ")\n";
    std::cout << "scene: " << loaded.name << ", " << loaded.triangleCount() << " triangles, "
              << loaded.lights.size() << " light(s), " << loaded.image.width << "x" << loaded.image.height
              << '\n';

    rhi::ShaderLibrary shaders(*device);
    gi::PipelineCache pipelines(*device, shaders);
    gi::GpuScene gpuScene(*device, loaded);
    gi::DeferredRenderer renderer(
        *device, loaded, gpuScene,
        {.width = loaded.image.width,
         .height = loaded.image.height,
         .exposureEv = exposure,
         .log = [](std::string_view line) { std::cout << "note: " << line << '\n'; }});

    gi::TimingTable table(warmup);
    rhi::CommandListHandle list = device->createCommandList();
    rhi::IQueue& queue = device->queue(rhi::QueueType::Graphics);
    for (uint32_t frameIndex = 0; frameIndex < frames; ++frameIndex) {
        list->begin();
        gi::FrameContext frame(pipelines, *list, frameIndex);
        renderer.render(frame);
        list->end();
        queue.waitForValue(queue.submit(*list));
        table.addFrame(list->timerResults(), frame.skipped());
    }

    image::writeDisplayPng(out, gi::displayImage(gi::readTextureImage(*device, *renderer.ldr())));
    std::cout << "wrote " << out.string() << '\n';
    if (args.has("exr")) {
        image::Image hdr = gi::readTextureImage(*device, *renderer.hdr());
        hdr.removeChannel("A");
        image::writeExr(args.get("exr"), hdr);
        std::cout << "wrote " << args.get("exr") << " (linear HDR radiance)\n";
    }
    if (args.has("dump-buffers")) {
        const auto written =
            gi::dumpDeferredBuffers(*device, renderer, args.get("dump-buffers"), {.exposureEv = exposure});
        std::cout << "wrote " << written.size() << " buffer images to " << args.get("dump-buffers") << '\n';
    }
    if (timings) {
        table.print(std::cout);
    }
    if (args.has("timings-json")) {
        table.writeJson(args.get("timings-json"), {{"commit", std::string(gi::gitCommit())},
                                                   {"device", device->adapter().name},
                                                   {"driver", device->adapter().driver},
                                                   {"api", std::string(rhi::apiName(device->api()))},
                                                   {"scene", loaded.name},
                                                   {"size", std::to_string(loaded.image.width) + "x" +
                                                                std::to_string(loaded.image.height)},
                                                   {"renderer", "deferred (direct light)"}});
        std::cout << "wrote " << args.get("timings-json") << '\n';
    }
    if (device->validationMessageCount() != 0) {
        std::cerr << "render: " << device->validationMessageCount() << " validation message(s)\n";
        return 1;
    }
    return 0;
}

} // namespace

Command renderCommand() {
    return {
        .name = "render",
        .summary = "render a scene with the real-time deferred renderer",
        .usage = "lumina render SCENE [--out img.png] [--exr img.exr] [--dump-buffers DIR] [--timings] "
                 "[--timings-json PATH] [--frames N] [--warmup N] [--exposure EV] [--size WxH]",
        .description =
            "Renders SCENE (a built-in name or a scene/glTF path) with the deferred renderer: GBuffer, sun "
            "shadow map, point and spot light cube shadows, direct light and the composite (direct + "
            "indirect x albedo; indirect is black until GI exists), then writes the tonemapped image as "
            "PNG (default <scene>.png). --exr writes the linear HDR radiance; --dump-buffers writes every "
            "intermediate target (GBuffer, shadow maps, direct light, HDR, LDR) as EXR and PNG. "
            "--timings runs N frames (default 60) and prints the median GPU time of each pass from "
            "timestamp queries, and how often each pass was skipped and why (shadow maps re-render "
            "only when their light or the geometry changes). docs/deferred.md describes the frame.",
        .flags = {{"exr", "PATH", "also write the linear HDR result as EXR"},
                  {"dump-buffers", "DIR", "write every intermediate buffer into DIR"},
                  {"timings", "", "print the GPU time per pass (runs 60 frames unless --frames)"},
                  {"timings-json", "PATH", "write the per-pass timings as JSON"},
                  {"warmup", "N", "frames left out of the timings (default 0)"},
                  {"exposure", "EV", "exposure in stops before the tonemap (default 0)"}},
        .run = runRender};
}

} // namespace lumina::app
