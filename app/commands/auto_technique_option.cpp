#include "app/commands/auto_technique_option.h"

#include "app/command.h"
#include "app/commands/number_text.h"
#include "app/commands/scene_options.h"
#include "gi/bench/reference_cache.h"
#include "gi/frame/gi_technique.h"
#include "gi/frame/preset.h"
#include "gi/scene/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

namespace lumina::app {

namespace {

std::string name(const gi::AutoCandidate& c) {
    return c.technique + " " + c.preset;
}

} // namespace

std::vector<FlagSpec> withCalibrationFlags(std::vector<FlagSpec> flags) {
    for (FlagSpec flag : std::vector<FlagSpec>{
             {"calibration-size", "WxH", "auto's calibration: image size (default 64x64)"},
             {"calibration-frames", "N", "auto's calibration: frames per candidate (default 128)"},
             {"calibration-spp", "N", "auto's calibration: samples of its reference (default 64)"}}) {
        flags.push_back(flag);
    }
    return flags;
}

std::vector<FlagSpec> withAutoTechniqueFlags(std::vector<FlagSpec> flags) {
    for (FlagSpec flag : std::vector<FlagSpec>{
             {"error-budget", "E",
              "with --technique auto: the largest relMSE against the path tracer allowed"},
             {"auto-techniques", "LIST",
              "with --technique auto: the candidates (default direct,lumen,ddgi,sh-grid)"},
             {"auto-presets", "LIST", "with --technique auto: their presets (default low,medium,high)"}}) {
        flags.push_back(flag);
    }
    return withCalibrationFlags(std::move(flags));
}

void requireAutoForAutoFlags(const ParsedArgs& args) {
    for (const char* flag : {"error-budget", "auto-techniques", "auto-presets", "calibration-size",
                             "calibration-frames", "calibration-spp"}) {
        if (args.has(flag)) {
            throw UsageError(std::string("--") + flag + " goes with --technique auto");
        }
    }
}

gi::CalibrationRequest calibrationRequest(const ParsedArgs& args) {
    gi::CalibrationRequest request;
    if (args.has("calibration-size")) {
        const ImageSize size = parseSize("calibration-size", args.get("calibration-size"));
        request.width = size.width;
        request.height = size.height;
    }
    request.frames = uint32_t(args.getUint("calibration-frames", request.frames, 1, 4096));
    request.referenceSpp = uint32_t(args.getUint("calibration-spp", request.referenceSpp, 1, 1u << 20));
    if (args.has("auto-techniques")) {
        request.techniques = parseList("auto-techniques", args.get("auto-techniques"));
    }
    if (args.has("auto-presets")) {
        request.presets = parseList("auto-presets", args.get("auto-presets"));
    }
    for (const std::string& technique : request.techniques) {
        if (technique == "pathtracer" || technique == "auto") {
            throw UsageError("--auto-techniques: '" + technique + "' is not a real-time technique");
        }
        try {
            gi::parseGiTechnique(technique);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--auto-techniques: ") + e.what());
        }
    }
    for (const std::string& preset : request.presets) {
        try {
            gi::findPreset(preset);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--auto-presets: ") + e.what());
        }
    }
    return request;
}

double errorBudget(const ParsedArgs& args) {
    if (!args.has("error-budget")) {
        throw UsageError("--technique auto needs --error-budget E (the largest relMSE allowed, e.g. 0.05)");
    }
    const double budget = args.getDouble("error-budget", 0.0);
    if (!(budget > 0.0) || !std::isfinite(budget)) {
        throw UsageError("--error-budget: must be a positive number, got " + args.get("error-budget"));
    }
    return budget;
}

void printCalibration(const gi::Calibration& calibration, const gi::CalibrationRequest& request,
                      double budget, std::optional<size_t> choice) {
    std::cout << "auto: calibration at " << request.width << "x" << request.height << ", " << request.frames
              << " frames per candidate, against a " << request.referenceSpp << "-spp path-traced reference ("
              << (calibration.reused ? "reused " : "measured, kept in ") << calibration.path.string()
              << ")\n";
    std::printf("  %-10s %-8s %14s %12s\n", "technique", "preset", "GPU ms/frame", "relMSE");
    for (size_t i = 0; i < calibration.candidates.size(); ++i) {
        const gi::AutoCandidate& c = calibration.candidates[i];
        std::printf("  %-10s %-8s %14s %12s  %s%s\n", c.technique.c_str(), c.preset.c_str(),
                    numberText(c.frameMs, 4).c_str(), numberText(c.relMse, 4).c_str(),
                    c.relMse <= budget ? "under the budget" : "over", choice == i ? ", chosen" : "");
    }
    std::fflush(stdout);
    if (!choice) {
        return;
    }
    const gi::AutoCandidate& chosen = calibration.candidates[*choice];
    std::cout << "auto: chose " << name(chosen) << ": relMSE " << numberText(chosen.relMse, 4)
              << " <= " << numberText(budget, 4) << " at " << numberText(chosen.frameMs, 4)
              << " GPU ms per frame, the cheapest under the budget";
    std::vector<std::string> cheaper;
    for (const gi::AutoCandidate& c : calibration.candidates) {
        if (c.frameMs < chosen.frameMs) {
            cheaper.push_back(name(c) + " (relMSE " + numberText(c.relMse, 4) + ")");
        }
    }
    if (!cheaper.empty()) {
        std::cout << "; the cheaper ones miss it:";
        for (size_t i = 0; i < cheaper.size(); ++i) {
            std::cout << (i ? ", " : " ") << cheaper[i];
        }
    }
    std::cout << '\n';
}

ParsedArgs chooseAutoTechnique(const ParsedArgs& args) {
    const double budget = errorBudget(args);
    if (args.has("preset")) {
        throw UsageError(
            "--preset with --technique auto: auto chooses the preset too (--auto-presets limits it)");
    }
    const gi::CalibrationRequest request = calibrationRequest(args);
    const scene::Scene scene = scene::loadScene(args.positional.front(), sceneLoadOptions(args));
    gi::Calibration calibration;
    {
        rhi::DeviceHandle device = openDevice(args.common);
        rhi::ShaderLibrary shaders(*device);
        gi::PipelineCache pipelines(*device, shaders);
        calibration =
            gi::loadOrCalibrate(*device, pipelines, scene, request, gi::defaultCalibrationDirectory(),
                                gi::defaultReferenceDirectory(), [](const gi::AutoCandidate& c) {
                                    std::cerr << "auto: measured " << name(c) << "\n";
                                });
        if (device->validationMessageCount() != 0) {
            throw std::runtime_error("auto: " + std::to_string(device->validationMessageCount()) +
                                     " validation message(s) during the calibration");
        }
    }
    const std::optional<size_t> choice = gi::cheapestUnder(calibration.candidates, budget);
    printCalibration(calibration, request, budget, choice);
    if (!choice) {
        const auto best = std::ranges::min_element(calibration.candidates, {}, &gi::AutoCandidate::relMse);
        throw std::runtime_error("auto: no candidate has relMSE <= " + numberText(budget, 4) +
                                 "; the most accurate is " + name(*best) + " at " +
                                 numberText(best->relMse, 4) + " (raise --error-budget)");
    }
    ParsedArgs chosen = args;
    chosen.set("technique", calibration.candidates[*choice].technique);
    chosen.set("preset", calibration.candidates[*choice].preset);
    return chosen;
}

} // namespace lumina::app
