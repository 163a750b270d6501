// `lumina bench`: the run-time-against-error matrix. For every scene it renders (or reuses) a
// path-traced reference, then runs each technique (direct, lumen, ddgi, sh-grid, pathtracer) at each quality
// preset for a fixed number of frames, timing every pass on the GPU and measuring the image
// against the reference at frame 1 and after convergence. Writes bench.csv, bench.json and a
// log-log plot of error against frame time (scripts/plot_bench.py, python3-matplotlib).
// docs/measurement.md.
#include "app/command.h"
#include "app/commands/scene_options.h"
#include "gi/bench/bench_report.h"
#include "gi/bench/change_response.h"
#include "gi/bench/reference_cache.h"
#include "gi/bench/technique_runs.h"
#include "gi/core/build_info.h"
#include "gi/core/pipeline_cache.h"
#include "gi/scene/builtin_scenes.h"
#include "gi/scene/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace lumina::app {

namespace {

constexpr const char* kDefaultScenes = "cornell_box,cornell_box_point,open_top_box";
// Lumen is asked for by name: on lavapipe its surface cache costs seconds a frame until it
// converges and the path tracer's budgets grow with it (docs/measurement.md).
constexpr const char* kDefaultTechniques = "direct,pathtracer";
constexpr const char* kDefaultPresets = "low,medium,high";
// The path tracer's per-frame budgets, in multiples of a real-time technique's frame time
// (equalTimeBase): equal time and two larger budgets, so its curve of error against time has
// three points.
constexpr const char* kDefaultBudgets = "1,4,16";
constexpr uint32_t kDefaultSize = 128;
constexpr uint32_t kDefaultFrames = 16;
constexpr uint32_t kDefaultReferenceSpp = 256;
// The path tracer under test: any seed but the reference's.
constexpr uint32_t kPathTracerSeed = 1;

std::vector<std::string> splitList(const std::string& flag, const std::string& text) {
    std::vector<std::string> items;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');) {
        if (item.empty()) {
            throw UsageError("--" + flag + ": empty item in '" + text + "'");
        }
        items.push_back(item);
    }
    if (items.empty()) {
        throw UsageError("--" + flag + ": give at least one item");
    }
    return items;
}

// The frame time the path tracer's budgets multiply: the median over presets of lumen's median
// frame when lumen ran (the GI technique it is the ground truth for), else of direct's, else
// one path-traced sample. Medians over the whole run, the frame_ms the plot puts on its x axis,
// so an equal-time point sits above the technique it matches.
gi::TimeBase equalTimeBase(const std::map<std::string, std::vector<double>>& realTimeFrameMs,
                           double msPerSample) {
    for (const char* technique : {"lumen", "direct"}) {
        if (const auto found = realTimeFrameMs.find(technique); found != realTimeFrameMs.end()) {
            return {.technique = technique, .ms = gi::median(found->second)};
        }
    }
    return {.technique = "pathtracer sample", .ms = msPerSample};
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
    return std::ranges::find(list, item) != list.end();
}

std::string number(double value, int digits = 4) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

void printRun(const std::string& scene, const gi::TechniqueRun& run) {
    const gi::Checkpoint& first = run.checkpoints.front();
    const gi::Checkpoint& last = run.checkpoints.back();
    std::cout << "  " << scene << " / " << run.technique << " / " << run.preset;
    if (run.samplesPerFrame) {
        std::cout << " (" << run.samplesPerFrame << " spp/frame)";
    }
    std::cout << ": " << number(run.frameMs) << " ms/frame, relMSE " << number(first.relMse) << " -> "
              << number(last.relMse) << " (frame " << run.framesToConverge << "), indirect relMSE "
              << number(last.indirectRelMse) << ", FLIP " << number(last.flip) << ", "
              << number(double(run.gpuMemoryBytes) / (1024.0 * 1024.0), 3) << " MiB";
    if (!run.settledAfterFrame) {
        std::cout << ", not settled";
    } else if (*run.settledAfterFrame > 1) {
        std::cout << ", settled after frame " << *run.settledAfterFrame;
        if (run.settledFrameMs) {
            std::cout << " (then " << number(*run.settledFrameMs) << " ms/frame)";
        }
    }
    std::cout << '\n';
}

// scripts/plot_bench.py from the source tree the built-in scenes come from.
std::filesystem::path plotScript() {
    if (const auto scenes = scene::findScenesDirectory()) {
        return scenes->parent_path() / "scripts" / "plot_bench.py";
    }
    return {};
}

// Debian's python3 first: python3-matplotlib is installed for it, whatever else PATH holds.
std::string pythonInterpreter() {
    if (const char* chosen = std::getenv("LUMINA_PYTHON"); chosen && *chosen) {
        return chosen;
    }
    return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

bool makePlot(const std::filesystem::path& csv, const std::filesystem::path& png) {
    const std::filesystem::path script = plotScript();
    if (script.empty() || !std::filesystem::exists(script)) {
        std::cerr << "bench: note: no plot, scripts/plot_bench.py not found (set LUMINA_SOURCE_DIR)\n";
        return false;
    }
    const std::string command = "\"" + pythonInterpreter() + "\" \"" + script.string() + "\" \"" +
                                csv.string() + "\" \"" + png.string() + "\"";
    if (std::system(command.c_str()) != 0) {
        std::cerr << "bench: note: the plot failed (it needs python3-matplotlib; LUMINA_PYTHON picks the "
                     "interpreter): "
                  << command << '\n';
        return false;
    }
    return true;
}

void printChangeResponse(const gi::ChangeResponse& r) {
    std::cout << "  " << r.scene << " / " << r.technique << " / " << r.preset << ": after " << r.changeFrames
              << " frames of change, relMSE " << number(r.relMseAtStop)
              << " against a fresh converged render (" << number(r.changedRegionRelMseAtStop) << " over the "
              << number(100.0 * r.changedRegionFraction, 3) << "% of pixels the change touched); ";
    if (r.framesToRecover) {
        std::cout << "within 0.01 after " << *r.framesToRecover << " frame(s) held still ("
                  << number(r.msToRecover) << " GPU ms)";
    } else {
        std::cout << "not within 0.01 in " << r.relMseAfter.size() << "+ checkpoints";
    }
    std::cout << "; frame " << number(r.movingFrameMs) << " ms moving, " << number(r.staticFrameMs)
              << " ms static\n";
}

int runBench(const ParsedArgs& args) {
    if (!args.positional.empty()) {
        throw UsageError("bench takes no positional arguments; name scenes with --scenes");
    }
    const std::vector<std::string> sceneNames = splitList("scenes", args.get("scenes", kDefaultScenes));
    const std::vector<std::string> techniques =
        splitList("techniques", args.get("techniques", kDefaultTechniques));
    const std::vector<std::string> presets = splitList("presets", args.get("presets", kDefaultPresets));
    std::vector<double> budgets;
    for (const std::string& item : splitList("pt-budgets", args.get("pt-budgets", kDefaultBudgets))) {
        const double budget = parseDouble("pt-budgets", item);
        if (!(budget > 0.0 && budget <= 1e6)) {
            throw UsageError("--pt-budgets: each budget must be in (0, 1e6], got " + item);
        }
        budgets.push_back(budget);
    }
    for (const std::string& technique : techniques) {
        if (!contains({"direct", "lumen", "ddgi", "sh-grid", "pathtracer"}, technique)) {
            throw UsageError("--techniques: unknown technique '" + technique +
                             "' (direct, lumen, ddgi, sh-grid, pathtracer)");
        }
    }
    for (const std::string& preset : presets) {
        try {
            gi::findPreset(preset);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--presets: ") + e.what());
        }
    }
    const uint32_t width = args.common.size ? args.common.size->width : kDefaultSize;
    const uint32_t height = args.common.size ? args.common.size->height : kDefaultSize;
    const uint32_t frames = args.common.frames.value_or(kDefaultFrames);
    if (frames == 0) {
        throw UsageError("--frames: at least one frame");
    }
    const auto referenceSpp = uint32_t(args.getUint("reference-spp", kDefaultReferenceSpp, 1, 1u << 20));
    const std::filesystem::path outDir = args.common.out.empty() ? "bench" : args.common.out;
    const std::filesystem::path cacheDir =
        args.has("cache") ? std::filesystem::path(args.get("cache")) : gi::defaultReferenceDirectory();

    // Load every scene first: a typo fails before any GPU work.
    std::vector<scene::Scene> scenes;
    for (const std::string& name : sceneNames) {
        scenes.push_back(scene::loadScene(name, sceneLoadOptions(args)));
    }
    std::filesystem::create_directories(outDir);

    rhi::DeviceHandle device = openDevice(args.common);
    const gi::BenchContext context{.commit = std::string(gi::gitCommit()),
                                   .device = device->adapter().name,
                                   .driver = device->adapter().driver,
                                   .api = std::string(rhi::apiName(device->api())),
                                   .date = gi::utcTimestamp(),
                                   .referenceSpp = referenceSpp};
    std::cout << "bench: " << context.device << " (" << context.api << ", driver " << context.driver
              << "), commit " << context.commit << "\n       " << scenes.size() << " scene(s) at " << width
              << "x" << height << ", " << frames << " frames per run, references " << referenceSpp
              << " spp in " << cacheDir.string() << '\n';
    rhi::ShaderLibrary shaders(*device);
    gi::PipelineCache pipelines(*device, shaders);

    std::vector<gi::BenchRecord> records;
    std::vector<gi::ChangeResponse> responses;
    const auto changeFrames = uint32_t(args.getUint("change-frames", 0, 0, 1u << 20));
    for (const scene::Scene& scene : scenes) {
        const gi::ReferenceRequest request{.width = width, .height = height, .spp = referenceSpp};
        const gi::Reference reference = gi::loadOrRenderReference(
            *device, pipelines, scene, request, cacheDir, [&](uint32_t done, uint32_t total) {
                if (done == total || done % std::max(total / 8, 1u) < 4) {
                    std::cerr << "  reference " << scene.name << ": " << done << "/" << total << " spp\n";
                }
            });
        std::cout << "  reference " << scene.name << ": " << (reference.reused ? "reused " : "rendered ")
                  << reference.path.string() << " (" << number(reference.seconds, 3) << " s)\n";

        const gi::RunRequest run{.width = width, .height = height, .frames = frames, .seed = kPathTracerSeed};
        std::map<std::string, std::vector<double>> realTimeFrameMs;
        for (const std::string& technique : techniques) {
            if (technique == "pathtracer") {
                continue;
            }
            for (const std::string& preset : presets) {
                records.push_back({scene.name,
                                   gi::runRealTime(*device, pipelines, scene, gi::parseGiTechnique(technique),
                                                   preset, run, reference),
                                   reference.path.string()});
                printRun(scene.name, records.back().run);
                realTimeFrameMs[technique].push_back(records.back().run.frameMs);
                if (changeFrames > 0 && !scene.animation.empty()) {
                    responses.push_back(gi::measureChangeResponse(
                        *device, pipelines, scene, gi::parseGiTechnique(technique), preset,
                        {.width = width, .height = height, .changeFrames = changeFrames}));
                    printChangeResponse(responses.back());
                }
            }
        }
        if (contains(techniques, "pathtracer")) {
            // Equal time: as many samples per frame as fit in the real-time frame (at least one,
            // which on a slow device costs more than equal time: the row's frame_ms says so).
            const double msPerSample = gi::pathTracerMsPerSample(*device, pipelines, scene, width, height);
            const gi::TimeBase base = equalTimeBase(realTimeFrameMs, msPerSample);
            std::cout << "  " << scene.name << " / pathtracer: budgets in multiples of " << base.technique
                      << " (" << number(base.ms) << " ms), " << number(msPerSample) << " ms per sample\n";
            for (double budget : budgets) {
                gi::RunRequest ptRun = run;
                ptRun.samplesPerFrame =
                    uint32_t(std::clamp(std::floor(budget * base.ms / msPerSample), 1.0, 65536.0));
                const std::string preset = number(budget, 3) + "x-time";
                records.push_back(
                    {scene.name, gi::runPathTracer(*device, pipelines, scene, preset, ptRun, reference),
                     reference.path.string(), gi::TimeBudget{.multiple = budget, .base = base}});
                printRun(scene.name, records.back().run);
            }
        }
    }

    const std::filesystem::path csv = outDir / "bench.csv", json = outDir / "bench.json",
                                png = outDir / "bench.png";
    gi::writeBenchCsv(csv, context, records);
    gi::writeBenchJson(json, context, records);
    std::cout << "wrote " << csv.string() << " and " << json.string() << '\n';
    if (!responses.empty()) {
        const std::filesystem::path changeCsv = outDir / "change_response.csv";
        gi::writeChangeResponseCsv(changeCsv, responses);
        std::cout << "wrote " << changeCsv.string() << '\n';
    }
    if (!args.has("no-plot") && makePlot(csv, png)) {
        std::cout << "wrote " << png.string() << '\n';
    }
    uint64_t nonFinite = 0;
    for (const gi::BenchRecord& record : records) {
        nonFinite += record.run.nonFinitePixels;
    }
    if (nonFinite != 0) {
        std::cerr << "bench: " << nonFinite << " NaN/Inf pixel(s) in the measured images\n";
        return 1;
    }
    if (device->validationMessageCount() != 0) {
        std::cerr << "bench: " << device->validationMessageCount() << " validation message(s)\n";
        return 1;
    }
    return 0;
}

} // namespace

Command benchCommand() {
    return {
        .name = "bench",
        .summary = "time every technique and preset and measure its error against the path tracer",
        .usage =
            "lumina bench [--scenes A,B] [--techniques direct,lumen,ddgi,sh-grid,pathtracer] [--presets "
            "low,medium,high] "
            "[--pt-budgets 1,4,16] [--size WxH] [--frames N] [--reference-spp N] [--cache DIR] [--out DIR] "
            "[--no-default-light] [--sky FILE.exr [--sky-intensity K]]",
        .description =
            "For each scene, renders a path-traced reference with AOVs (or reuses the one cached for the "
            "same "
            "scene, size, samples and seed), then runs each technique at each preset for --frames frames "
            "(default 16) at --size (default 128x128). direct is the deferred renderer (presets set its "
            "shadow-map sizes); lumen adds the lumen GI (SDFs, surface cache, screen probes), ddgi the DDGI "
            "probe volumes on the same SDFs and surface cache (docs/ddgi.md), sh-grid the SH probe grid "
            "baked "
            "from raster cube maps (docs/sh_grid.md; presets are "
            "the one table of docs/gi.md, shadow maps included); the path tracer accumulates across frames "
            "with "
            "per-frame budgets in multiples of a real-time frame: lumen's median frame when lumen runs, else "
            "direct's (samples per frame chosen from its measured cost, at least 1). Per configuration it "
            "records the median GPU time per frame and per pass (timestamp queries), the settled frame time "
            "(median over the frames after lumen's surface cache converged), relMSE of the final image and "
            "of "
            "the indirect term (what indirect light adds at the primary hit) against the reference at frame "
            "1 "
            "and after the last frame, mean FLIP, the frames to converge (first checkpoint within 5% of the "
            "final error), the GPU memory held and the NaN/Inf pixels. Writes DIR/bench.csv, DIR/bench.json "
            "(default DIR: bench) with the commit, device, driver and API, and DIR/bench.png, error against "
            "frame time on log-log axes (python3-matplotlib). lumen and ddgi are not in the default list: on "
            "lavapipe they cost seconds a frame until the surface cache converges; name them with "
            "--techniques. "
            "docs/measurement.md has the columns.",
        .flags = withSceneLoadFlags(
            {{"scenes", "LIST",
              "comma-separated scenes (default cornell_box,cornell_box_point,open_top_box)"},
             {"techniques", "LIST", "direct, lumen, ddgi, sh-grid, pathtracer (default direct,pathtracer)"},
             {"presets", "LIST", "presets of direct and lumen: low, medium, high (default all)"},
             {"pt-budgets", "LIST",
              "path-tracer frame budgets in multiples of lumen's frame, else direct's (default 1,4,16)"},
             {"reference-spp", "N", "samples per pixel of the references (default 256)"},
             {"cache", "DIR", "where references are kept (default $LUMINA_CACHE_DIR/references)"},
             {"no-plot", "", "write the CSV and JSON only"},
             {"change-frames", "N",
              "for animated scenes: play N frames of the animation, hold the pose, and measure the frames "
              "and GPU ms until each real-time run is within relMSE 0.01 of a fresh converged render of that "
              "pose, and the frame cost moving against static (DIR/change_response.csv)"}}),
        .run = runBench};
}

} // namespace lumina::app
