// `lumina bench`: the run-time-against-error matrix. For every scene it renders (or reuses) a
// path-traced reference, then runs each technique (direct, lumen, ddgi, sh-grid, pathtracer) at each quality
// preset for a fixed number of frames, timing every pass on the GPU and measuring the image
// against the reference at frame 1 and after convergence. Writes bench.csv, bench.json and a
// log-log plot of error against frame time (scripts/plot_bench.py, python3-matplotlib).
// docs/measurement.md.
#include "app/command.h"
#include "app/commands/auto_technique_option.h"
#include "app/commands/bench_auto_check.h"
#include "app/commands/bench_plot.h"
#include "app/commands/number_text.h"
#include "app/commands/scene_options.h"
#include "app/commands/shard_option.h"
#include "gi/bench/bench_matrix.h"
#include "gi/bench/bench_report.h"
#include "gi/bench/bench_shards.h"
#include "gi/bench/change_response.h"
#include "gi/bench/reference_cache.h"
#include "gi/bench/skip_check.h"
#include "gi/bench/technique_runs.h"
#include "gi/core/build_info.h"
#include "gi/core/pipeline_cache.h"
#include "gi/scene/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <numeric>
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

void printRun(const std::string& scene, const gi::TechniqueRun& run) {
    const gi::Checkpoint& first = run.checkpoints.front();
    const gi::Checkpoint& last = run.checkpoints.back();
    std::cout << "  " << scene << " / " << run.technique << " / " << run.preset;
    if (run.samplesPerFrame) {
        std::cout << " (" << run.samplesPerFrame << " spp/frame)";
    }
    std::cout << ": " << numberText(run.frameMs, 4) << " ms/frame, relMSE " << numberText(first.relMse, 4)
              << " -> " << numberText(last.relMse, 4) << " (frame " << run.framesToConverge
              << "), indirect relMSE " << numberText(last.indirectRelMse, 4) << ", FLIP "
              << numberText(last.flip, 4) << ", "
              << numberText(double(run.gpuMemoryBytes) / (1024.0 * 1024.0), 3) << " MiB";
    if (!run.settledAfterFrame) {
        std::cout << ", not settled";
    } else if (*run.settledAfterFrame > 1) {
        std::cout << ", settled after frame " << *run.settledAfterFrame;
        if (run.settledFrameMs) {
            std::cout << " (then " << numberText(*run.settledFrameMs, 4) << " ms/frame)";
        }
    }
    std::cout << '\n';
}

void printChangeResponse(const gi::ChangeResponse& r) {
    std::cout << "  " << r.scene << " / " << r.technique << " / " << r.preset << ": after " << r.changeFrames
              << " frames of change, relMSE " << numberText(r.relMseAtStop, 4)
              << " against a fresh converged render (" << numberText(r.changedRegionRelMseAtStop, 4)
              << " over the " << numberText(100.0 * r.changedRegionFraction, 3)
              << "% of pixels the change touched); ";
    if (r.framesToRecover) {
        std::cout << "within 0.01 after " << *r.framesToRecover << " frame(s) held still ("
                  << numberText(r.msToRecover, 4) << " GPU ms)";
    } else {
        std::cout << "not within 0.01 in " << r.relMseAfter.size() << "+ checkpoints";
    }
    std::cout << "; frame " << numberText(r.movingFrameMs, 4) << " ms moving, "
              << numberText(r.staticFrameMs, 4) << " ms static\n";
}

void printSkipCheck(const gi::SkipCheck& c) {
    std::cout << "  skip check " << c.scene << " / " << c.technique << " / " << c.preset << ": '" << c.pass
              << "' (" << c.reason << ", " << c.framesSkipped << " frame(s)): ";
    if (!c.forceable) {
        std::cout << "nothing to run, cannot be forced\n";
        return;
    }
    std::cout << "saves " << numberText(c.savedMs(), 4) << " ms a frame (" << numberText(c.frameMs, 4)
              << " -> " << numberText(c.forcedFrameMs, 4) << " forced"
              << (c.framesSkippedForced
                      ? ", still skipped in " + std::to_string(c.framesSkippedForced) + " forced frame(s)"
                      : std::string())
              << "), image relMSE " << numberText(c.imageRelMse, 4)
              << " without it: " << (c.withinTolerance() ? "within " : "OVER ")
              << numberText(gi::kSkipImageTolerance, 4) << '\n';
}

int runBench(const ParsedArgs& args) {
    if (!args.positional.empty()) {
        throw UsageError("bench takes no positional arguments; name scenes with --scenes");
    }
    const std::vector<std::string> sceneNames = parseList("scenes", args.get("scenes", kDefaultScenes));
    const std::vector<std::string> techniques =
        parseList("techniques", args.get("techniques", kDefaultTechniques));
    const std::vector<std::string> presets = parseList("presets", args.get("presets", kDefaultPresets));
    std::vector<double> budgets;
    for (const std::string& item : parseList("pt-budgets", args.get("pt-budgets", kDefaultBudgets))) {
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

    const std::optional<gi::Shard> shard = parseShardFlag(args);
    if (args.has("check-auto")) {
        const double budget = args.getDouble("check-auto", 0.0);
        if (!(budget > 0.0) || !std::isfinite(budget)) {
            throw UsageError("--check-auto: must be a positive relMSE, got " + args.get("check-auto"));
        }
        if (shard) {
            throw UsageError(
                "--check-auto with --shard: the check needs the whole matrix; run it on the merged "
                "results' scenes without --shard");
        }
        calibrationRequest(args); // its flags checked before any GPU work
    }
    const auto changeFrames = uint32_t(args.getUint("change-frames", 0, 0, 1u << 20));
    const gi::BenchMatrix matrix{.scenes = sceneNames.size(),
                                 .techniques = techniques,
                                 .presets = presets.size(),
                                 .budgets = budgets.size()};
    // The units this run takes: all, or every n-th from the shard's index on.
    const std::vector<gi::BenchUnit> allUnits = gi::benchUnits(matrix);
    std::vector<gi::BenchUnit> units;
    for (size_t k = 0; k < allUnits.size(); ++k) {
        if (!shard || k % shard->count == shard->index) {
            units.push_back(allUnits[k]);
        }
    }
    if (units.empty()) {
        throw UsageError("--shard " + shard->text() + ": the matrix has " + std::to_string(allUnits.size()) +
                         " units (scene x real-time technique, the path tracer going with " +
                         "the technique its budgets multiply): use at most " +
                         std::to_string(allUnits.size()) + " shards");
    }
    const auto runs = [&](size_t scene, const std::string& technique) {
        return std::ranges::any_of(units, [&](const gi::BenchUnit& u) {
            return u.scene == scene &&
                   (u.technique == technique || (technique == "pathtracer" && u.withPathTracer));
        });
    };

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
    if (shard) {
        std::cout << "       shard " << shard->text() << ": " << units.size() << " of " << allUnits.size()
                  << " units\n";
    }
    rhi::ShaderLibrary shaders(*device);
    gi::PipelineCache pipelines(*device, shaders);

    std::vector<gi::BenchRecord> records;
    std::vector<gi::ChangeResponse> responses;
    std::vector<gi::SkipCheck> skipChecks;
    gi::BenchShardManifest manifest{.shard = shard.value_or(gi::Shard{}), .totalRows = matrix.rowCount()};
    for (size_t s = 0; s < scenes.size(); ++s) {
        const scene::Scene& scene = scenes[s];
        if (!std::ranges::any_of(units, [&](const gi::BenchUnit& u) { return u.scene == s; })) {
            continue;
        }
        const gi::ReferenceRequest request{.width = width, .height = height, .spp = referenceSpp};
        const gi::Reference reference = gi::loadOrRenderReference(
            *device, pipelines, scene, request, cacheDir, [&](uint32_t done, uint32_t total) {
                if (done == total || done % std::max(total / 8, 1u) < 4) {
                    std::cerr << "  reference " << scene.name << ": " << done << "/" << total << " spp\n";
                }
            });
        std::cout << "  reference " << scene.name << ": " << (reference.reused ? "reused " : "rendered ")
                  << reference.path.string() << " (" << numberText(reference.seconds, 3) << " s)\n";

        const gi::RunRequest run{.width = width, .height = height, .frames = frames, .seed = kPathTracerSeed};
        std::map<std::string, std::vector<double>> realTimeFrameMs;
        const bool verifySkips = args.has("verify-skips");
        for (const std::string& technique : matrix.realTimeTechniques()) {
            if (!runs(s, technique)) {
                continue;
            }
            for (size_t p = 0; p < presets.size(); ++p) {
                const std::string& preset = presets[p];
                records.push_back({scene.name,
                                   gi::runRealTime(*device, pipelines, scene, gi::parseGiTechnique(technique),
                                                   preset, run, reference),
                                   reference.path.string()});
                manifest.rows.push_back(matrix.realTimeRow(s, technique, p));
                printRun(scene.name, records.back().run);
                realTimeFrameMs[technique].push_back(records.back().run.frameMs);
                if (verifySkips) {
                    for (gi::SkipCheck& check :
                         gi::checkSkips(*device, pipelines, scene, gi::parseGiTechnique(technique), preset,
                                        run, reference, records.back().run)) {
                        printSkipCheck(check);
                        skipChecks.push_back(std::move(check));
                    }
                }
                if (changeFrames > 0 && !scene.animation.empty()) {
                    responses.push_back(gi::measureChangeResponse(
                        *device, pipelines, scene, gi::parseGiTechnique(technique), preset,
                        {.width = width, .height = height, .changeFrames = changeFrames}));
                    manifest.changeRows.push_back(manifest.rows.back());
                    printChangeResponse(responses.back());
                }
            }
        }
        if (matrix.hasPathTracer() && runs(s, "pathtracer")) {
            // Equal time: as many samples per frame as fit in the real-time frame (at least one,
            // which on a slow device costs more than equal time: the row's frame_ms says so).
            const double msPerSample = gi::pathTracerMsPerSample(*device, pipelines, scene, width, height);
            const gi::TimeBase base = equalTimeBase(realTimeFrameMs, msPerSample);
            std::cout << "  " << scene.name << " / pathtracer: budgets in multiples of " << base.technique
                      << " (" << numberText(base.ms, 4) << " ms), " << numberText(msPerSample, 4)
                      << " ms per sample\n";
            for (size_t b = 0; b < budgets.size(); ++b) {
                const double budget = budgets[b];
                gi::RunRequest ptRun = run;
                ptRun.samplesPerFrame =
                    uint32_t(std::clamp(std::floor(budget * base.ms / msPerSample), 1.0, 65536.0));
                const std::string preset = numberText(budget, 3) + "x-time";
                records.push_back(
                    {scene.name, gi::runPathTracer(*device, pipelines, scene, preset, ptRun, reference),
                     reference.path.string(), gi::TimeBudget{.multiple = budget, .base = base}});
                manifest.rows.push_back(matrix.pathTracerRow(s, b));
                printRun(scene.name, records.back().run);
            }
        }
    }

    // Within one scene the path tracer's rows come last whichever unit ran them: put this
    // run's rows in one run's order (a whole run's are already).
    std::vector<size_t> order(records.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::ranges::sort(order, {}, [&](size_t i) { return manifest.rows[i]; });
    std::vector<gi::BenchRecord> sorted;
    std::vector<size_t> sortedRows;
    for (size_t i : order) {
        sorted.push_back(records[i]);
        sortedRows.push_back(manifest.rows[i]);
    }
    records = std::move(sorted);
    manifest.rows = std::move(sortedRows);

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
    if (args.has("verify-skips")) {
        const std::filesystem::path skipsCsv = outDir / "skips.csv";
        gi::writeSkipChecksCsv(skipsCsv, skipChecks);
        std::cout << "wrote " << skipsCsv.string() << '\n';
    }
    if (shard) {
        manifest.run = {.scenes = sceneNames,
                        .techniques = techniques,
                        .presets = presets,
                        .budgets = budgets,
                        .width = width,
                        .height = height,
                        .frames = frames,
                        .referenceSpp = referenceSpp,
                        .changeFrames = changeFrames};
        for (const scene::Scene& scene : scenes) {
            manifest.run.sceneDigests.push_back(gi::sceneDigest(scene));
        }
        gi::writeBenchShardManifest(outDir, manifest);
        std::cout << "wrote " << (outDir / "shard.json").string() << " (lumina merge makes the plot)\n";
    } else if (!args.has("no-plot") && makeBenchPlot(csv, png)) {
        std::cout << "wrote " << png.string() << '\n';
    }
    if (args.has("check-auto")) {
        const std::filesystem::path autoCsv = outDir / "auto_check.csv";
        const size_t differ = checkAutoChoices(*device, pipelines, args, scenes, matrix.realTimeTechniques(),
                                               presets, records, autoCsv);
        std::cout << "wrote " << autoCsv.string() << " (auto's choice differs from the matrix's on " << differ
                  << " of " << scenes.size() << " scene(s))\n";
    }
    const auto changing =
        std::ranges::count_if(skipChecks, [](const gi::SkipCheck& c) { return !c.withinTolerance(); });
    if (changing != 0) {
        std::cerr << "bench: " << changing << " skip(s) change the image by more than relMSE "
                  << numberText(gi::kSkipImageTolerance, 4) << " (DIR/skips.csv)\n";
        return 1;
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
            "[--shard i/n] [--verify-skips] [--check-auto E [--calibration-size WxH] [--calibration-frames "
            "N] "
            "[--calibration-spp N]] "
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
            "docs/measurement.md has the columns. With --shard i/n it runs only units i, i+n, i+2n... of "
            "the matrix (a unit: one scene and one real-time technique at every preset; the path tracer's "
            "budgets go with the technique they multiply) and writes their rows with DIR/shard.json and no "
            "plot; `lumina merge OUT DIR...` makes one run's files from the n shards (docs/batch.md).",
        .flags = withCalibrationFlags(withSceneLoadFlags(
            {{"scenes", "LIST",
              "comma-separated scenes (default cornell_box,cornell_box_point,open_top_box)"},
             {"techniques", "LIST", "direct, lumen, ddgi, sh-grid, pathtracer (default direct,pathtracer)"},
             {"presets", "LIST", "presets of direct and lumen: low, medium, high (default all)"},
             {"pt-budgets", "LIST",
              "path-tracer frame budgets in multiples of lumen's frame, else direct's (default 1,4,16)"},
             {"reference-spp", "N", "samples per pixel of the references (default 256)"},
             {"cache", "DIR", "where references are kept (default $LUMINA_CACHE_DIR/references)"},
             {"no-plot", "", "write the CSV and JSON only"},
             shardFlag("run units i, i+n, ... of the n-way split matrix only (0 <= i < n), for lumina merge"),
             {"check-auto", "E",
              "after the matrix, compare what render --technique auto --error-budget E chooses per scene "
              "(its "
              "calibration, --calibration-*) with the matrix's cheapest configuration under E "
              "(DIR/auto_check.csv); not with --shard"},
             {"verify-skips", "",
              "after each real-time run, run it again with each skip of unchanged work forced off (a shadow "
              "map redrawn, radiosity refined on, the SH grid rebaked...): the GPU ms a frame each skip "
              "saves "
              "and the image's relMSE without it, which must be at most 0.001, else exit 1 "
              "(DIR/skips.csv; docs/measurement.md#skips)"},
             {"change-frames", "N",
              "for animated scenes: play N frames of the animation, hold the pose, and measure the frames "
              "and GPU ms until each real-time run is within relMSE 0.01 of a fresh converged render of that "
              "pose, and the frame cost moving against static (DIR/change_response.csv)"}})),
        .run = runBench};
}

} // namespace lumina::app
