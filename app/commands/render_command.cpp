// `lumina render SCENE`: the real-time frame (GBuffer, sun and point-light shadows, direct
// light, and with the lumen technique the surface cache and the screen-probe gather, then the
// composite) rendered on the GPU and written as a PNG, optionally with the linear HDR result as
// EXR, every intermediate buffer, and the GPU time of each pass.
#include "app/command.h"
#include "app/commands/auto_technique_option.h"
#include "app/commands/ddgi_options.h"
#include "app/commands/scene_options.h"
#include "app/commands/sh_grid_options.h"
#include "gi/core/build_info.h"
#include "gi/core/frame_context.h"
#include "gi/core/pipeline_cache.h"
#include "gi/core/timing_table.h"
#include "gi/deferred/buffer_readback.h"
#include "gi/frame/frame_dump.h"
#include "gi/frame/frame_finite_check.h"
#include "gi/frame/frame_renderer.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/image/exr.h"
#include "gi/image/png.h"
#include "gi/scene/scene_animation.h"
#include "gi/scene/scene_loader.h"
#include "rhi/rhi.h"
#include "shaders/ddgi/ddgi_shared.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace lumina::app {

namespace {

// Frames run with --timings and no --frames: enough for a stable median on a real GPU and
// for the skipped shadow passes to show in the table.
constexpr uint32_t kTimingFrames = 60;
// Lumen without --frames runs until the surface cache's radiosity has converged, then this
// many frames more for the screen probes' temporal filters (about 10% new a frame: 0.9^48 < 1%),
// and never more than kMaxConvergeFrames.
constexpr uint32_t kProbeSettleFrames = 48;
constexpr uint32_t kMaxConvergeFrames = 2000;
// More than three frames ahead only adds latency: the GPU is busy either way.
constexpr uint32_t kMaxFramesInFlight = 3;

// --mesh-sdf-resolution and --global-sdf-resolution, for the techniques that trace SDFs.
void applySdfResolutionFlags(const ParsedArgs& args, const scene::Scene& scene,
                             gi::FrameRendererSettings& settings) {
    gi::GiSceneSettings* traced = settings.lumen  ? static_cast<gi::GiSceneSettings*>(&*settings.lumen)
                                  : settings.ddgi ? static_cast<gi::GiSceneSettings*>(&*settings.ddgi)
                                                  : nullptr;
    for (const char* flag : {"mesh-sdf-resolution", "global-sdf-resolution"}) {
        if (args.has(flag) && traced == nullptr) {
            throw UsageError(std::string("--") + flag +
                             " applies only to the techniques that trace SDFs (lumen, ddgi)");
        }
    }
    if (args.has("mesh-sdf-resolution")) {
        gi::setMeshSdfResolution(
            *traced,
            static_cast<uint32_t>(
                args.getUint("mesh-sdf-resolution", 0, gi::kMinMeshSdfResolution, gi::kMaxMeshSdfResolution)),
            scene);
    }
    if (args.has("global-sdf-resolution")) {
        gi::setGlobalSdfResolution(*traced, static_cast<uint32_t>(args.getUint("global-sdf-resolution", 0,
                                                                               gi::kMinGlobalSdfResolution,
                                                                               gi::kMaxGlobalSdfResolution)));
    }
}

gi::FrameRendererSettings rendererSettings(const ParsedArgs& args, const scene::Scene& scene,
                                           float exposure) {
    gi::FrameRendererSettings settings;
    const std::string technique =
        args.get("technique", scene.technique.empty() ? gi::kDefaultTechnique : scene.technique);
    const std::string preset = args.get("preset", scene.preset.empty() ? gi::kDefaultPreset : scene.preset);
    const gi::Preset* shadows = nullptr;
    try {
        settings.technique = gi::parseGiTechnique(technique);
        shadows = &gi::findPreset(preset);
        if (settings.technique == gi::GiTechnique::Lumen) {
            settings.lumen = gi::lumenPreset(*shadows, scene);
            settings.lumen->probes.probeSpacing =
                static_cast<uint32_t>(args.getUint("probe-spacing", settings.lumen->probes.probeSpacing,
                                                   gi::kMinProbeSpacing, gi::kMaxProbeSpacing));
            settings.lumen->probes.raysPerProbe =
                static_cast<uint32_t>(args.getUint("rays-per-probe", settings.lumen->probes.raysPerProbe,
                                                   gi::kMinRaysPerProbe, gi::kMaxRaysPerProbe));
            if (args.has("adaptive-probes")) {
                settings.lumen->probes.adaptiveProbeFraction =
                    static_cast<float>(args.getDouble("adaptive-probes", 0.0));
            }
            if (args.has("near-field-distance")) {
                settings.lumen->probes.nearFieldDistance =
                    static_cast<float>(args.getDouble("near-field-distance", 0.0));
            }
            settings.lumen->probes.validate();
        }
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    if (settings.technique == gi::GiTechnique::Ddgi) {
        settings.ddgi = ddgiSettings(args, *shadows, scene);
    }
    if (settings.technique == gi::GiTechnique::ShGrid) {
        settings.shGrid = shGridSettings(args, *shadows, scene);
    }
    applySdfResolutionFlags(args, scene, settings);
    settings.deferred = {.width = scene.image.width,
                         .height = scene.image.height,
                         .sunShadowSize = shadows->sunShadowSize,
                         .pointShadowSize = shadows->pointShadowSize,
                         .exposureEv = exposure,
                         .log = [](std::string_view line) { std::cout << "note: " << line << '\n'; }};
    return settings;
}

// Whether the technique's surface cache has settled (radiosity converged); always for direct.
bool surfacesSettled(const gi::FrameRenderer& renderer) {
    return renderer.gi() == nullptr || renderer.gi()->converged();
}

// GPU memory per subsystem, as allocated while each was built.
void printMemory(const gi::FrameRenderer& renderer, uint64_t sceneBytes, uint64_t rendererBytes) {
    const auto mib = [](uint64_t bytes) {
        std::ostringstream text;
        text << std::fixed << std::setprecision(1) << double(bytes) / (1024.0 * 1024.0) << " MiB";
        return text.str();
    };
    std::cout << "GPU memory: scene " << mib(sceneBytes);
    uint64_t gi = 0;
    if (renderer.gi() != nullptr) {
        for (const gi::GiMemoryPart& part : renderer.gi()->memory()) {
            gi += part.bytes;
            std::cout << ", " << part.name << ' ' << mib(part.bytes);
        }
    }
    std::cout << ", deferred " << mib(rendererBytes - gi) << ", total " << mib(sceneBytes + rendererBytes)
              << '\n';
}

int renderWith(const ParsedArgs& args) {
    const bool timings = args.has("timings") || args.has("timings-json");
    if (args.common.frames && *args.common.frames == 0) {
        throw UsageError("--frames: at least one frame");
    }
    const auto exposure = static_cast<float>(args.getDouble("exposure", 0.0));
    const std::string asyncMode = args.get("async-compute", "auto");
    if (asyncMode != "auto" && asyncMode != "on" && asyncMode != "off") {
        throw UsageError("--async-compute: '" + asyncMode + "' is not auto, on or off");
    }

    scene::Scene loaded = scene::loadScene(args.positional.front(), sceneLoadOptions(args));
    if (args.common.size) {
        loaded.image = {args.common.size->width, args.common.size->height};
    }
    // An animated scene plays its animation (docs/dynamic_scenes.md) unless --animation-frame poses
    // it at one frame and holds it still.
    const bool heldStill = poseAtAnimationFrame(args, loaded);
    const bool animated = !heldStill && !loaded.animation.empty();
    const std::filesystem::path out = args.common.out.empty() ? loaded.name + ".png" : args.common.out;
    // A name ending in .exr asks for the linear image; writing a PNG under that name (as this
    // once did) leaves a file every EXR reader rejects.
    const bool outIsExr = out.extension() == ".exr";
    if (!outIsExr && out.extension() != ".png") {
        throw UsageError("--out " + out.string() +
                         ": the image is written as .png (display) or .exr (linear HDR)");
    }
    // Before the frames, not after them: a lumen render runs for minutes on a CPU device, and
    // an output folder that does not exist yet should not cost them.
    for (const std::filesystem::path& file : {out, std::filesystem::path(args.get("exr"))}) {
        if (file.has_parent_path()) {
            std::filesystem::create_directories(file.parent_path());
        }
    }

    rhi::DeviceHandle device = openDevice(args.common);
    std::cout << "device: " << device->adapter().name << " (" << rhi::apiName(device->api()) << ", driver "
              << device->adapter().driver << ")\n";
    std::cout << "scene: " << loaded.name << ", " << loaded.triangleCount() << " triangles, "
              << loaded.lights.size() << " light(s), " << loaded.image.width << "x" << loaded.image.height
              << '\n';
    std::cout << lightingLine(loaded) << '\n';

    gi::FrameRendererSettings settings = rendererSettings(args, loaded, exposure);
    const bool lumen = settings.technique == gi::GiTechnique::Lumen;
    const bool ddgi = settings.technique == gi::GiTechnique::Ddgi;
    const bool shGrid = settings.technique == gi::GiTechnique::ShGrid;
    const bool withGi = lumen || ddgi || shGrid;
    // Direct light is final after one frame; lumen converges (see kProbeSettleFrames), DDGI's
    // probes once their history has forgotten the frames before the cache converged. An animation
    // plays once through unless --frames says how long.
    const bool converge = withGi && !args.common.frames && !animated;
    // The SH grid is final once every probe is baked: nothing to settle after.
    const uint32_t settleFrames = ddgi     ? gi::ddgiSettleUpdates(settings.ddgi->hysteresis)
                                  : shGrid ? 0u
                                           : kProbeSettleFrames;
    const uint32_t loopFrames =
        animated ? std::max<uint32_t>(
                       1u, uint32_t(std::ceil(loaded.animation.length() * double(loaded.framesPerSecond))))
                 : 1u;
    const uint32_t frames = args.common.frames.value_or(converge   ? kMaxConvergeFrames
                                                        : animated ? loopFrames
                                                        : timings  ? kTimingFrames
                                                                   : 1u);
    const auto warmup = static_cast<uint32_t>(args.getUint("warmup", 0, 0, frames - 1));
    std::cout << "technique: " << gi::giTechniqueName(settings.technique);
    if (lumen) {
        std::cout << ", preset "
                  << args.get("preset", loaded.preset.empty() ? gi::kDefaultPreset : loaded.preset)
                  << " (atlas " << settings.lumen->cache.atlasSize << "^2, probes every "
                  << settings.lumen->probes.probeSpacing << " px, " << settings.lumen->probes.raysPerProbe
                  << " rays each)";
    }
    if (ddgi) {
        const gi::DdgiSettings& d = *settings.ddgi;
        const auto counts = [](const glm::uvec3& c) {
            return std::to_string(c.x) + "x" + std::to_string(c.y) + "x" + std::to_string(c.z) + " probes";
        };
        std::cout << ", preset "
                  << args.get("preset", loaded.preset.empty() ? gi::kDefaultPreset : loaded.preset) << " ("
                  << (!d.volumes.empty() ? std::to_string(d.volumes.size()) + " volume(s) from the scene file"
                      : d.cascades > 0   ? std::to_string(d.cascades) + " camera-centred cascades of " +
                                             counts(d.probeCounts)
                                       : "one volume of " + counts(d.probeCounts) + " fitted to the scene")
                  << ", " << d.raysPerProbe << " rays each, hysteresis " << d.hysteresis << ")";
    }
    if (shGrid) {
        const gi::ShGridSettings& g = *settings.shGrid;
        const gi::ShGridLayout grid = gi::fitShGrid(g, loaded.worldBounds());
        std::cout << ", preset "
                  << args.get("preset", loaded.preset.empty() ? gi::kDefaultPreset : loaded.preset) << " ("
                  << grid.counts.x << "x" << grid.counts.y << "x" << grid.counts.z << " probes, "
                  << g.faceSize << "^2 cube faces, " << g.probesPerFrame << " probes baked per frame, "
                  << g.sweeps << " sweeps" << (g.loadPath.empty() ? "" : ", loaded from " + g.loadPath)
                  << ")";
    }
    std::cout << '\n';

    rhi::ShaderLibrary shaders(*device);
    gi::PipelineCache pipelines(*device, shaders);
    const uint64_t baseBytes = device->allocatedMemoryBytes();
    gi::GpuScene gpuScene(*device, loaded);
    const uint64_t sceneBytes = device->allocatedMemoryBytes();
    gi::FrameRenderer renderer(*device, loaded, gpuScene, std::move(settings));
    printMemory(renderer, sceneBytes - baseBytes, device->allocatedMemoryBytes() - sceneBytes);

    gi::TimingTable table(warmup);
    // Frames in flight: frame n records into list n % count while the GPU still runs the frames
    // before it; a list's begin() waits only for that list's previous submission (count frames
    // back). Nothing the renderer reads on the CPU comes back from the GPU during a frame, its
    // uploads live in each list's own upload memory, and every list starts with a full barrier
    // (rhi/command_list.h), so frames that overlap on the CPU stay in order on the GPU.
    const auto inFlight = static_cast<uint32_t>(args.getUint("frames-in-flight", 2, 1, kMaxFramesInFlight));
    // Async compute (docs/performance.md, change 3): each frame is recorded into three lists, and
    // the GI passes that read nothing of the frame's raster run on the compute queue beside it.
    // By default only where the compute queue is hardware of its own: on a shared queue the split
    // costs two more submissions a frame and overlaps nothing.
    // --check-finite scans after each pass of one list: it records every frame on one.
    const bool asyncCompute =
        !args.has("check-finite") &&
        (asyncMode == "on" || (asyncMode == "auto" && device->capabilities().separateComputeQueue));
    struct InFlightFrame {
        rhi::CommandListHandle list;   // the whole frame; with async compute, its raster
        rhi::CommandListHandle async;  // with async compute: the compute queue's list
        rhi::CommandListHandle gather; // with async compute: the GI after the raster, the composite
        std::vector<gi::SkippedPass> skipped;
        uint64_t fence = 0;      // the graphics queue value its last submission signals; 0: none pending
        uint64_t asyncFence = 0; // the compute queue's; 0: none pending
    };
    std::vector<InFlightFrame> slots(inFlight);
    for (InFlightFrame& slot : slots) {
        slot.list = device->createCommandList();
        if (asyncCompute) {
            slot.async = device->createCommandList(rhi::QueueType::Compute);
            slot.gather = device->createCommandList();
        }
    }
    rhi::IQueue& queue = device->queue(rhi::QueueType::Graphics);
    rhi::IQueue& computeQueue = device->queue(rhi::QueueType::Compute);
    // A slot's previous frame, once finished: its timers into the table.
    const auto retire = [&](InFlightFrame& slot) {
        if (slot.asyncFence != 0) {
            computeQueue.waitForValue(slot.asyncFence);
        }
        if (slot.fence != 0) {
            queue.waitForValue(slot.fence);
            std::vector<rhi::TimerResult> timers = slot.list->timerResults();
            // The async list counts only when it was submitted (it holds no passes otherwise).
            for (rhi::ICommandList* more :
                 {slot.asyncFence != 0 ? slot.async.get() : nullptr, slot.gather.get()}) {
                if (more != nullptr) {
                    std::vector<rhi::TimerResult> results = more->timerResults();
                    timers.insert(timers.end(), results.begin(), results.end());
                }
            }
            table.addFrame(timers, slot.skipped);
            slot.fence = 0;
            slot.asyncFence = 0;
        }
    };
    // --check-finite: every pass's float outputs scanned after it; each frame waited for and its
    // first non-finite write, if any, is an error naming the pass and the resource.
    std::optional<gi::FiniteCheck> finiteCheck;
    if (args.has("check-finite")) {
        finiteCheck.emplace(*device);
        gi::watchFloatBuffers(*finiteCheck, renderer);
    }
    uint64_t lastGraphicsFence = 0;
    uint32_t asyncFrames = 0; // frames whose GI ran partly on the compute queue
    // Records frame `frameIndex` into `slot` and submits it; returns its skipped passes.
    const auto recordAndSubmit = [&](InFlightFrame& slot, uint32_t frameIndex) {
        slot.list->begin();
        gi::FrameContext frame(pipelines, *slot.list, frameIndex);
        if (!asyncCompute) {
            if (finiteCheck) {
                finiteCheck->beginFrame(frame);
            }
            renderer.render(frame);
            slot.list->end();
            lastGraphicsFence = slot.fence = queue.submit(*slot.list);
            return frame.skipped();
        }
        slot.async->begin();
        slot.gather->begin();
        gi::FrameContext async(pipelines, *slot.async, frameIndex);
        gi::FrameContext gather(pipelines, *slot.gather, frameIndex);
        const bool besideRaster = renderer.render(gi::SplitFrame{frame, async, gather});
        slot.list->end();
        slot.async->end();
        slot.gather->end();
        if (besideRaster) {
            // The async passes rewrite what the previous frame's gather read: they start after it.
            if (lastGraphicsFence != 0) {
                computeQueue.waitForQueue(queue, lastGraphicsFence);
            }
            slot.asyncFence = computeQueue.submit(*slot.async);
            ++asyncFrames;
        }
        queue.submit(*slot.list);
        if (besideRaster) {
            queue.waitForQueue(computeQueue, slot.asyncFence);
        }
        lastGraphicsFence = slot.fence = queue.submit(*slot.gather);
        std::vector<gi::SkippedPass> skipped = frame.skipped();
        for (const gi::FrameContext* part : {&async, &gather}) {
            skipped.insert(skipped.end(), part->skipped().begin(), part->skipped().end());
        }
        return skipped;
    };
    std::vector<double> wallMs;
    auto lastFrameEnd = std::chrono::steady_clock::now();
    uint32_t settledAt = 0; // the frame after which the surface cache had converged; 0: not yet
    uint32_t rendered = 0;
    scene::Scene posed = animated ? loaded : scene::Scene{};
    gi::SceneChangeStats changes;
    uint32_t changedFrames = 0;
    for (uint32_t frameIndex = 0; frameIndex < frames; ++frameIndex) {
        if (animated) {
            scene::animateScene(posed, frameIndex);
            renderer.applyScene(posed);
        }
        InFlightFrame& slot = slots[frameIndex % inFlight];
        retire(slot);
        slot.skipped = recordAndSubmit(slot, frameIndex);
        if (renderer.lastChanges().any()) {
            ++changedFrames;
            changes.movedInstances += renderer.lastChanges().movedInstances;
            changes.changedLights += renderer.lastChanges().changedLights;
            changes.changedMaterials += renderer.lastChanges().changedMaterials;
        }
        if (finiteCheck) {
            retire(slot);
            if (const std::optional<gi::NonFiniteWrite> bad = finiteCheck->report()) {
                throw std::runtime_error("--check-finite: " + bad->describe());
            }
        }
        const auto now = std::chrono::steady_clock::now();
        if (frameIndex >= warmup) {
            wallMs.push_back(std::chrono::duration<double, std::milli>(now - lastFrameEnd).count());
        }
        lastFrameEnd = now;
        rendered = frameIndex + 1;
        if (settledAt == 0 && surfacesSettled(renderer)) {
            settledAt = rendered;
        }
        if (withGi && (rendered % 16 == 0 || rendered == frames)) {
            std::cerr << "frame " << rendered << (converge ? "" : "/" + std::to_string(frames))
                      << (shGrid      ? (settledAt ? ": sh grid baked" : ": sh grid baking")
                          : settledAt ? ": surface cache converged"
                                      : ": surface cache converging")
                      << '\n';
        }
        if (converge && settledAt != 0 && rendered >= settledAt + settleFrames) {
            break;
        }
    }
    // The frames still in flight, oldest first, so the table keeps frame order.
    for (uint32_t i = 0; i < inFlight; ++i) {
        retire(slots[(rendered + i) % inFlight]);
    }
    if (finiteCheck) {
        std::cout << "check-finite: " << rendered << " frame(s), " << finiteCheck->checksLastFrame()
                  << " pass outputs checked in the last; no NaN or Inf\n";
    }
    if (timings && !wallMs.empty()) {
        std::cout << "wall time: " << std::fixed << std::setprecision(3) << gi::median(wallMs)
                  << " ms a frame (median from frame " << warmup << ", CPU recording and submission with "
                  << inFlight << " frame(s) in flight)" << std::defaultfloat << '\n';
    }
    if (asyncCompute) {
        std::cout << "async compute: " << asyncFrames << " of " << rendered
                  << " frame(s) ran GI passes on the compute queue ("
                  << (device->capabilities().separateComputeQueue ? "a separate hardware queue"
                                                                  : "this device's compute queue shares the "
                                                                    "graphics hardware queue")
                  << "); the frame row of the timings sums passes that overlapped, the wall time does not\n";
    }
    if (animated) {
        std::cout << "animation: " << rendered << " frame(s) played (a loop is " << loopFrames << " at "
                  << loaded.framesPerSecond << " frames/s); " << changedFrames
                  << " frame(s) changed the scene: " << changes.movedInstances << " instance move(s), "
                  << changes.changedLights << " light change(s), " << changes.changedMaterials
                  << " emission change(s)\n";
    }
    if (shGrid) {
        std::cout << "frames: " << rendered << " (sh grid "
                  << (settledAt ? "baked after " + std::to_string(settledAt) : std::string("not fully baked"))
                  << ")\n";
    }
    if (withGi && !shGrid) {
        std::cout << "frames: " << rendered << " (surface cache "
                  << (settledAt ? "converged after " + std::to_string(settledAt)
                                : std::string("not converged"))
                  << ")\n";
        const surface_cache::SurfaceCache& cache =
            lumen ? renderer.lumen()->surfaceCache() : renderer.ddgi()->surfaceCache();
        const surface_cache::SurfaceCache::LodHistory& lod = cache.lodHistory();
        std::cout << "surface cache: atlas " << cache.atlas().size() << "^2, "
                  << surface_cache::toString(cache.cards().occupancy()) << '\n'
                  << "surface cache LOD: " << lod.updates << " re-plans, " << lod.evictions
                  << " evictions (at most " << lod.maxEvictionsPerUpdate << " in a frame), "
                  << lod.pendingCaptures << " captures pending\n";
    }
    if (lumen) {
        const gi::ScreenProbeResources& r = renderer.lumen()->screenProbes().resources();
        const uint32_t slots = r.probeCount - r.uniformProbeCount;
        std::cout << "screen probes: " << r.uniformProbeCount << " uniform, ";
        if (slots == 0) {
            std::cout << "no adaptive (--adaptive-probes 0)\n";
        } else {
            // More wanted than the rows hold: the slots are shared evenly over the image and the other
            // tiles go without (--adaptive-probes raises the room).
            const uint32_t wanted = renderer.lumen()->screenProbes().adaptiveProbesWanted(*device);
            std::cout << std::min(wanted, slots) << " adaptive in the last frame (room for " << slots << ")";
            std::cout << (wanted > slots ? ", " + std::to_string(wanted - slots) + " tiles went without" : "")
                      << '\n';
        }
    }
    if (ddgi) {
        const gi::DdgiProbeCounts probes = renderer.ddgi()->probeCounts(*device);
        std::cout << "ddgi probes: " << probes.total() << ", " << probes.inactive
                  << " inactive (classified off: only their " << LUMINA_DDGI_FIXED_RAYS
                  << " fixed rays traced, never blended), " << probes.active + probes.fresh << " active\n";
    }

    if (shGrid && args.has("sh-grid-save")) {
        gi::saveShGrid(args.get("sh-grid-save"), renderer.shGrid()->readGrid(*device));
        std::cout << "wrote " << args.get("sh-grid-save") << " (the baked SH grid)\n";
    }

    const auto writeHdr = [&](const std::filesystem::path& path) {
        image::Image hdr = gi::readTextureImage(*device, *renderer.deferred().hdr());
        hdr.removeChannel("A");
        image::writeExr(path, hdr);
        std::cout << "wrote " << path.string() << " (linear HDR radiance)\n";
    };
    if (outIsExr) {
        writeHdr(out);
    } else {
        image::writeDisplayPng(out,
                               gi::displayImage(gi::readTextureImage(*device, *renderer.deferred().ldr())));
        std::cout << "wrote " << out.string() << '\n';
    }
    if (args.has("exr")) {
        writeHdr(args.get("exr"));
    }
    if (args.has("dump-buffers")) {
        const auto written =
            gi::dumpFrameBuffers(*device, renderer, args.get("dump-buffers"), {.exposureEv = exposure});
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
                                                   {"technique", gi::giTechniqueName(renderer.technique())},
                                                   {"frames", std::to_string(rendered)}});
        std::cout << "wrote " << args.get("timings-json") << '\n';
    }
    if (device->validationMessageCount() != 0) {
        std::cerr << "render: " << device->validationMessageCount() << " validation message(s)\n";
        return 1;
    }
    return 0;
}

int runRender(const ParsedArgs& args) {
    if (args.positional.size() != 1) {
        throw UsageError("render takes one scene: a built-in name or a .json, .gltf or .glb path (see lumina "
                         "render --help)");
    }
    if (args.get("technique") == "auto") {
        return renderWith(chooseAutoTechnique(args));
    }
    requireAutoForAutoFlags(args);
    return renderWith(args);
}

} // namespace

Command renderCommand() {
    return {
        .name = "render",
        .summary = "render a scene in real time: deferred direct light plus GI (lumen)",
        .usage =
            "lumina render SCENE [--technique direct|lumen|ddgi|sh-grid] [--preset low|medium|high] "
            "[--technique auto --error-budget E] [--out img.png] "
            "[--exr img.exr] [--dump-buffers DIR] [--check-finite] [--timings] [--timings-json PATH] "
            "[--frames N] [--warmup N] [--frames-in-flight N] [--async-compute auto|on|off] [--exposure EV] "
            "[--size WxH] [--no-default-light] "
            "[--sky FILE.exr "
            "[--sky-intensity K]]",
        .description =
            "Renders SCENE (a built-in name or a scene/glTF path) in real time: GBuffer, sun shadow map, "
            "point and spot light cube shadows and direct light (docs/deferred.md); with the lumen "
            "technique (the default) the scene's SDFs, the surface cache with multi-bounce radiosity "
            "(docs/surface_cache.md) and the screen-probe final gather (docs/screen_probes.md) add "
            "indirect light; the composite (direct + indirect x albedo) is tonemapped and written as PNG "
            "(default <scene>.png), or kept linear when --out names an .exr. The technique and preset come "
            "from the flags, else the scene file, "
            "else lumen and medium (docs/gi.md lists what each preset sets). Without --frames, lumen runs "
            "until the surface cache converges and the probes settle (progress on stderr), direct one "
            "frame (60 with --timings). --exr writes the linear HDR radiance; --dump-buffers writes every "
            "intermediate (GBuffer, shadow maps, direct light, indirect term, every surface-cache layer, "
            "card outlines and ids, radiosity probes, voxel lighting, the cache's light under each pixel "
            "(surface_cache_at_pixels.exr: against a reference, the cache's own error), every screen-probe "
            "buffer) as EXR "
            "and PNG. --check-finite scans, after every pass of every frame, the float textures the pass "
            "wrote (and the screen probes' float4 buffers) with a small kernel counting NaN and Inf, and "
            "stops at "
            "the first frame with one: an error (exit 1) naming the first pass, in recording order, that "
            "wrote a non-finite value and the texture or buffer (docs/gi_tests.md#poison); it waits for each "
            "frame. --timings prints the median GPU time of each pass from timestamp queries and how "
            "often each pass was skipped and why (shadow maps and surface-cache passes run only when "
            "something they read changed). A scene with an animation (glTF channels or scripted changes, "
            "docs/scenes.md) plays it, one loop unless --frames, and only what each frame changed is "
            "recomputed (docs/dynamic_scenes.md); --animation-frame F renders the pose at frame F "
            "still, converged like a static scene. --technique auto --error-budget E picks the technique "
            "and preset: a calibration renders every candidate (--auto-techniques x --auto-presets) at "
            "--calibration-size for --calibration-frames frames, times each on the GPU and measures its "
            "relMSE against a --calibration-spp path-traced reference of that size; the cheapest "
            "candidate (median GPU ms per frame) with relMSE <= E renders, after the table of candidates "
            "and the reason for the choice are printed. The table is cached under "
            "$LUMINA_CACHE_DIR/calibration, keyed by the scene's contents, the calibration and the build; "
            "no candidate under E is an error (exit 1) naming the most accurate one "
            "(docs/measurement.md).",
        .flags = withAutoTechniqueFlags(withSceneLoadFlags(withShGridFlags(withDdgiFlags(
            {{"technique", "NAME",
              "GI technique: direct (none), lumen, ddgi, sh-grid, or auto (with --error-budget; default: "
              "the scene's, else lumen)"},
             {"preset", "NAME", "quality preset: low, medium or high (default: the scene's, else medium)"},
             {"probe-spacing", "N", "pixels per screen-probe edge (overrides the preset; 2..64)"},
             {"rays-per-probe", "N", "rays per screen probe (overrides the preset; 16..256)"},
             {"adaptive-probes", "F",
              "room for adaptive screen probes, where a pixel lies on no uniform probe's surface, as a "
              "share of the uniform grid's probes (0..1; 0: none; default 0.25)"},
             {"near-field-distance", "D",
              "screen-probe near-field trace length in scene units; beyond it the far field (0: far field "
              "only; default: the preset's, 15 % of the scene's largest extent at low, the whole trace at "
              "medium and high)"},
             {"mesh-sdf-resolution", "N",
              "lumen and ddgi: voxels along each mesh's longest axis in its SDF (8..512; default 64): finer "
              "resolves thinner walls and gaps; memory and build time grow as N^3"},
             {"global-sdf-resolution", "N",
              "lumen and ddgi: voxels along the scene's longest axis in the global SDF, or per side of each "
              "cascade where the scene has cascades (16..256; default 64): finer lets the surface cache's "
              "rays through narrower openings; memory grows as N^3, and a large scene whose finer fitted "
              "grid is detailed enough gets that one grid instead of cascades (`lumina sdf SCENE "
              "--global-resolution N` shows which)"},
             {"exr", "PATH", "also write the linear HDR result as EXR"},
             {"dump-buffers", "DIR", "write every intermediate buffer into DIR"},
             {"check-finite", "",
              "after every pass, scan what it wrote for NaN/Inf; the first found is an error naming the pass "
              "and the buffer (a debug mode: waits for each frame, and records it on one queue, without "
              "--async-compute)"},
             {"timings", "", "print the GPU time per pass (direct: 60 frames unless --frames)"},
             {"timings-json", "PATH", "write the per-pass timings as JSON"},
             {"warmup", "N", "frames left out of the timings (default 0)"},
             {"frames-in-flight", "N",
              "frames recorded ahead of the GPU, 1..3 (default 2; 1 waits for each frame before the next)"},
             {"async-compute", "MODE",
              "auto, on or off: run the GI passes that read nothing of the frame's raster (the surface "
              "cache's and DDGI's probe updates, when no card is captured or relit) on the compute queue "
              "beside the raster (default auto: on where the device has a separate compute queue; "
              "docs/performance.md)"},
             {"exposure", "EV", "exposure in stops before the tonemap (default 0)"},
             {"animation-frame", "F",
              "pose an animated scene at frame F and hold it still (default: play the animation, one loop "
              "unless --frames)"}})))),
        .run = runRender};
}

} // namespace lumina::app
