// `lumina sdf SCENE`: builds (or loads from the cache) every mesh SDF of a scene, packs the
// atlas, composes the global SDF on the GPU, and on request writes a slice of it, a normal
// view traced through the SDFs, and a trace throughput benchmark (docs/sdf.md).
#include "app/command.h"
#include "app/commands/scene_options.h"
#include "gi/core/frame_context.h"
#include "gi/core/pipeline_cache.h"
#include "gi/core/timing_table.h"
#include "gi/image/png.h"
#include "gi/scene/generators/generators.h"
#include "gi/scene/scene_loader.h"
#include "gi/sdf/sdf_cache.h"
#include "gi/sdf/sdf_views.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace lumina::app {

namespace {

// Width of the normal view and of the benchmark's ray grid without --size: small enough
// for lavapipe; the height follows the scene's aspect ratio.
constexpr uint32_t kDefaultViewWidth = 256;
constexpr uint32_t kDefaultBenchFrames = 10;
constexpr uint32_t kBenchWarmupFrames = 2;
// Cone half-angle of the benchmark's cone traces, radians (the thesis's far-field cone).
constexpr float kBenchConeHalfAngle = 0.1f;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string dimsString(const glm::uvec3& d) {
    return std::to_string(d.x) + "x" + std::to_string(d.y) + "x" + std::to_string(d.z);
}

void printBuildReport(const sdf::SceneSdfData& data, bool cacheUsed) {
    const sdf::SceneSdfReport& report = data.report;
    for (const sdf::MeshSdfReport& mesh : report.meshes) {
        if (mesh.sharedWith != sdf::kNoVolume) {
            std::printf("  mesh %u '%s': %s voxels, %u triangles: same geometry as mesh %u, shares its SDF\n",
                        mesh.mesh, mesh.name.c_str(), dimsString(mesh.dims).c_str(), mesh.triangles,
                        mesh.sharedWith);
            continue;
        }
        std::printf("  mesh %u '%s': %s voxels, %u triangles%s: %s in %.3f s%s\n", mesh.mesh,
                    mesh.name.c_str(), dimsString(mesh.dims).c_str(), mesh.triangles,
                    mesh.open ? ", open" : "", mesh.fromCache ? "loaded from cache" : "built", mesh.seconds,
                    mesh.fromCache || mesh.note.empty() ? "" : (" (cache: " + mesh.note + ")").c_str());
    }
    std::printf(
        "mesh SDFs: %zu meshes, %u built (%llu voxels), %u loaded from cache (%llu voxels), %u sharing "
        "another's, in %.3f s%s\n",
        report.meshes.size(), report.meshesBuilt, static_cast<unsigned long long>(report.voxelsBuilt),
        report.meshesLoaded, static_cast<unsigned long long>(report.voxelsLoaded), report.meshesShared,
        report.meshSeconds,
        report.buildThreads == 0 ? ""
                                 : (" on " + std::to_string(report.buildThreads) + " thread(s)").c_str());
    if (report.voxelsBuilt == 0 && !report.meshes.empty()) {
        std::printf("mesh SDFs: loaded from cache, 0 voxels built\n");
    }
    if (!cacheUsed) {
        std::printf("mesh SDFs: cache off (--no-cache)\n");
    }
    const sdf::SdfAtlas& atlas = data.atlas;
    std::printf("atlas: %s texels %s, %.2f MiB, packed in %.3f s\n", dimsString(atlas.dims).c_str(),
                atlas.format == sdf::SdfTexelFormat::R16F ? "R16F" : "R32F",
                double(atlas.byteSize()) / (1024.0 * 1024.0), report.packSeconds);
    std::printf("instances: %zu with an SDF\n", data.instances.size());
    const sdf::GlobalSdfCascadeLayout& cascades = data.cascades;
    const double globalMiB = double(sdf::cascadeBytes(cascades)) / (1024.0 * 1024.0);
    std::printf("global SDF: %u cascade(s), %s (RG32F, %.2f MiB)", cascades.count,
                sdf::describeCascades(cascades).c_str(), globalMiB);
    if (cascades.scrolls()) {
        std::printf(", following the camera; median instance %.4g, finest voxel wanted %.4g\n",
                    data.medianInstanceSize, data.finestVoxelWanted);
    } else {
        std::printf(", scene-fitted; median instance %.4g\n", data.medianInstanceSize);
    }
    std::printf("SDF memory: %.2f MiB (atlas %.2f + global %.2f)\n",
                double(atlas.byteSize()) / (1024.0 * 1024.0) + globalMiB,
                double(atlas.byteSize()) / (1024.0 * 1024.0), globalMiB);
}

sdf::SdfField parseField(const std::string& name) {
    if (name == "near") {
        return sdf::SdfField::Near;
    }
    if (name == "far") {
        return sdf::SdfField::Far;
    }
    if (name == "cone") {
        return sdf::SdfField::Cone;
    }
    throw UsageError("--field: '" + name + "' is not one of near, far, cone");
}

// Submits `list` and waits; returns its timers.
std::vector<rhi::TimerResult> submitAndWait(rhi::IDevice& device, rhi::ICommandList& list) {
    rhi::IQueue& queue = device.queue(list.queueType());
    queue.waitForValue(queue.submit(list));
    return list.timerResults();
}

void runBenchmark(rhi::IDevice& device, gi::PipelineCache& pipelines, const sdf::SceneSdf& sdfs,
                  const scene::Scene& loaded, uint32_t width, uint32_t height, uint32_t frames) {
    sdf::SdfCameraTracer tracer(device, width, height);
    const float maxDistance = loaded.camera.farPlane;
    const float tanCone = std::tan(kBenchConeHalfAngle);
    const sdf::SdfField fields[] = {sdf::SdfField::Near, sdf::SdfField::Far, sdf::SdfField::Cone};
    gi::TimingTable table(kBenchWarmupFrames);
    rhi::CommandListHandle list = device.createCommandList();
    for (uint32_t frame = 0; frame < frames + kBenchWarmupFrames; ++frame) {
        list->begin();
        gi::FrameContext context(pipelines, *list, frame);
        for (sdf::SdfField field : fields) {
            tracer.record(context, sdfs, loaded.camera, field, sdf::defaultTraceParams(field, maxDistance),
                          std::string("sdf trace: ") + sdf::fieldName(field), tanCone);
        }
        list->end();
        table.addFrame(submitAndWait(device, *list), context.skipped());
    }
    const double rays = double(width) * height;
    std::printf("trace benchmark: %ux%u camera rays of '%s', median of %u frames after %u warm-up\n", width,
                height, loaded.name.c_str(), frames, kBenchWarmupFrames);
    for (const gi::PassTiming& pass : table.passes()) {
        if (pass.name == "frame") {
            continue;
        }
        std::printf("  %-24s %10.3f ms GPU  %8.3f Mrays/s\n", pass.name.c_str(), pass.medianMs,
                    pass.medianMs > 0.0 ? rays / (pass.medianMs * 1e3) : 0.0);
    }
}

// Records the global SDF's compose for a camera at `camera` as frame `index`, submits it and
// prints what it recomposed and its GPU time.
void recordCompose(rhi::IDevice& device, gi::PipelineCache& pipelines, rhi::ICommandList& list,
                   sdf::SceneSdf& sdfs, const glm::vec3& camera, uint64_t index) {
    list.begin();
    gi::FrameContext frame(pipelines, list, index);
    sdfs.record(frame, camera);
    list.end();
    const std::vector<rhi::TimerResult> timers = submitAndWait(device, list);
    const sdf::GlobalComposeStats& compose = sdfs.lastCompose();
    std::printf("global SDF compose, camera (%.4g %.4g %.4g): %s, %u bricks (%llu voxels) in %.3f ms GPU\n",
                camera.x, camera.y, camera.z, compose.reason.c_str(), compose.bricks,
                static_cast<unsigned long long>(compose.voxels),
                timers.empty() ? 0.0 : timers.front().milliseconds);
}

int runSdf(const ParsedArgs& args) {
    if (args.positional.size() != 1) {
        throw UsageError("sdf takes one scene: a built-in name or a scene path (see lumina sdf --help)");
    }
    scene::LoadOptions loadOptions = sceneLoadOptions(args);
    if (args.has("instances")) {
        loadOptions.instances = uint32_t(args.getUint("instances", 0, 1, scene::kCityMaxBuildings));
    }
    const auto loadStart = std::chrono::steady_clock::now();
    scene::Scene loaded = scene::loadScene(args.positional.front(), loadOptions);
    std::printf("scene %s: %zu meshes, %zu instances, %llu triangles in meshes (loaded in %.3f s)\n",
                loaded.name.c_str(), loaded.meshes.size(), loaded.instances.size(),
                static_cast<unsigned long long>(loaded.meshTriangleCount()), secondsSince(loadStart));

    sdf::SceneSdfSettings settings;
    settings.mesh.resolution = uint32_t(args.getUint("resolution", 64, 4, 512));
    settings.globalResolution = uint32_t(args.getUint("global-resolution", 64, 8, 1024));
    settings.useCache = !args.has("no-cache");
    if (args.has("r32f")) {
        settings.atlasFormat = sdf::SdfTexelFormat::R32F;
    }
    std::printf("mesh SDF resolution %u, cache %s\n", settings.mesh.resolution,
                settings.useCache ? sdf::SdfCache::defaultDirectory().generic_string().c_str() : "off");
    sdf::SceneSdfData data = sdf::buildSceneSdfData(loaded, settings);
    printBuildReport(data, settings.useCache);
    if (args.has("build-only")) {
        return 0;
    }

    rhi::DeviceHandle device = openDevice(args.common);
    std::printf("device: %s (%s, driver %s)\n", device->adapter().name.c_str(),
                std::string(rhi::apiName(device->api())).c_str(), device->adapter().driver.c_str());
    rhi::ShaderLibrary shaders(*device);
    gi::PipelineCache pipelines(*device, shaders);
    const auto uploadStart = std::chrono::steady_clock::now();
    sdf::SceneSdf sdfs(*device, std::move(data));
    std::printf("upload: %.3f s\n", secondsSince(uploadStart));

    rhi::CommandListHandle list = device->createCommandList();
    const sdf::GlobalSdfSettings& grid = sdfs.data().global;
    recordCompose(*device, pipelines, *list, sdfs, sdfs.data().camera, 0);
    for (uint32_t c = 0; c < sdfs.data().cascades.count; ++c) {
        const sdf::GlobalSdfSettings cascade = sdfs.cascadeGrid(c);
        const glm::vec3 far = cascade.boundsMin + glm::vec3(cascade.dims) * cascade.voxelSize;
        std::printf(
            "  cascade %u: %s voxels of %.4g over (%.4g %.4g %.4g)-(%.4g %.4g %.4g), truncated at %.4g\n", c,
            dimsString(cascade.dims).c_str(), cascade.voxelSize, cascade.boundsMin.x, cascade.boundsMin.y,
            cascade.boundsMin.z, far.x, far.y, far.z, cascade.maxDistance);
    }
    if (args.has("camera-step")) {
        // The camera walks along +x: what each step recomposes and what it costs.
        const uint32_t voxels = uint32_t(args.getUint("camera-step", 4, 1, 1024));
        const glm::vec3 step(float(voxels) * sdfs.data().cascades.finestVoxelSize, 0.0f, 0.0f);
        for (uint32_t i = 1; i <= 4; ++i) {
            recordCompose(*device, pipelines, *list, sdfs, sdfs.data().camera + float(i) * step, i);
        }
    }

    if (args.has("slice-png")) {
        const sdf::GlobalSdf global = sdf::readGlobalSdf(*device, sdfs);
        const uint32_t z = uint32_t(args.getUint("slice-z", grid.dims.z / 2, 0, grid.dims.z - 1));
        const std::string path = args.get("slice-png");
        image::writeDisplayPng(path, sdf::globalSdfSliceImage(global, z, grid.maxDistance));
        std::printf("wrote %s (z slice %u of %u)\n", path.c_str(), z, grid.dims.z);
    }

    uint32_t width = kDefaultViewWidth;
    uint32_t height = std::max(1u, uint32_t(std::lround(float(kDefaultViewWidth) / loaded.aspect())));
    if (args.common.size) {
        width = args.common.size->width;
        height = args.common.size->height;
    }
    if (args.has("normals-png")) {
        const sdf::SdfField field = parseField(args.get("field", "near"));
        sdf::SdfCameraTracer tracer(*device, width, height);
        list->begin();
        gi::FrameContext view(pipelines, *list, 1);
        tracer.record(view, sdfs, loaded.camera, field,
                      sdf::defaultTraceParams(field, loaded.camera.farPlane), "sdf: normal view",
                      std::tan(kBenchConeHalfAngle));
        list->end();
        submitAndWait(*device, *list);
        const std::string path = args.get("normals-png");
        image::writeDisplayPng(path, tracer.readNormals(*device));
        std::printf("wrote %s (%ux%u, %s)\n", path.c_str(), width, height, sdf::fieldName(field));
    }
    if (args.has("trace-bench")) {
        runBenchmark(*device, pipelines, sdfs, loaded, width, height,
                     args.common.frames.value_or(kDefaultBenchFrames));
    }
    if (device->validationMessageCount() != 0) {
        std::fprintf(stderr, "sdf: %llu validation message(s)\n",
                     static_cast<unsigned long long>(device->validationMessageCount()));
        return 1;
    }
    return 0;
}

} // namespace

Command sdfCommand() {
    return {
        .name = "sdf",
        .summary = "build a scene's mesh SDFs and global SDF; slice, normal view, trace benchmark",
        .usage =
            "lumina sdf SCENE [--resolution N] [--global-resolution N] [--slice-png PATH] "
            "[--normals-png PATH] [--trace-bench] [--camera-step N] [--build-only] [--no-cache] [--size WxH]"
            " [--no-default-light] [--sky FILE.exr [--sky-intensity K]]",
        .description =
            "Builds every mesh SDF of SCENE (N voxels along each mesh's longest axis), or loads it from the "
            "cache ($LUMINA_CACHE_DIR/sdf, else the user cache folder), printing each mesh's time and the "
            "totals; a run that builds nothing prints 'loaded from cache, 0 voxels built'. Then packs the "
            "atlas, uploads it and composes the global SDF on the GPU (N voxels along the scene's longest "
            "axis, or clipmap cascades of N^3 around the scene camera for a scene too large for that), "
            "printing its layout and the SDF memory (with --build-only too). --slice-png writes a z slice of "
            "the global SDF (its finest cascade), --normals-png a normal view from the "
            "scene camera traced through the SDFs (--field near|far|cone), --trace-bench the GPU time and "
            "rays per second of camera rays traced through each field (--size, --frames). docs/sdf.md has "
            "the details and measured figures.",
        .flags = withSceneLoadFlags(
            {{"resolution", "N", "mesh SDF voxels along each mesh's longest axis (default 64)"},
             {"global-resolution", "N",
              "global SDF voxels along the scene's longest axis, or per cascade side (default 64)"},
             {"slice-png", "PATH", "write a colour-mapped z slice of the global SDF"},
             {"slice-z", "N", "the slice's voxel index along z (default: the middle)"},
             {"normals-png", "PATH", "write the scene camera's normal view traced through the SDFs"},
             {"field", "NAME", "what --normals-png traces: near (default), far or cone"},
             {"trace-bench", "", "measure trace throughput (rays/s) of each field"},
             {"instances", "N", "building count of a generated city (default 1024)"},
             {"camera-step", "N",
              "then move the camera 4 times by N finest global voxels along +x, printing each recompose"},
             {"build-only", "", "stop after building the mesh SDFs (no GPU)"},
             {"no-cache", "", "build every mesh SDF, neither loading nor storing the cache"},
             {"r32f", "", "store the atlas as R32F instead of R16F"}}),
        .run = runSdf};
}

} // namespace lumina::app
