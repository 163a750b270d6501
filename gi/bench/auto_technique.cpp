#include "gi/bench/auto_technique.h"

#include "gi/bench/reference_cache.h"
#include "gi/bench/technique_runs.h"
#include "gi/core/build_info.h"
#include "gi/core/cache_dir.h"
#include "gi/frame/gi_technique.h"
#include "gi/sdf/sdf_cache.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

namespace lumina::gi {

namespace {

// Bump when what a calibration measures changes for the same inputs: old tables then miss.
constexpr uint32_t kCalibrationFormatVersion = 1;
constexpr uint32_t kCalibrationSeed = 1; // of the real-time runs; the reference has its own

uint64_t hashText(const std::string& text, uint64_t hash) {
    return sdf::fnv1a64(text.data(), text.size(), hash);
}

uint64_t calibrationKey(const scene::Scene& scene, const CalibrationRequest& request) {
    const uint32_t fields[] = {kCalibrationFormatVersion, request.width, request.height, request.frames,
                               request.referenceSpp};
    uint64_t hash = sdf::fnv1a64(fields, sizeof(fields), sceneDigest(scene));
    for (const std::string& technique : request.techniques) {
        hash = hashText(technique + ",", hash);
    }
    for (const std::string& preset : request.presets) {
        hash = hashText(preset + ";", hash);
    }
    return hashText(std::string(gitCommit()), hash);
}

std::optional<std::vector<AutoCandidate>> readTable(const std::filesystem::path& path, size_t expected) {
    std::ifstream in(path);
    if (!in) {
        return std::nullopt;
    }
    try {
        std::vector<AutoCandidate> candidates;
        const nlohmann::json table = nlohmann::json::parse(in); // kept: the loop reads into it
        for (const nlohmann::json& entry : table.at("candidates")) {
            candidates.push_back({entry.at("technique").get<std::string>(),
                                  entry.at("preset").get<std::string>(), entry.at("frame_ms").get<double>(),
                                  entry.at("relmse").get<double>()});
        }
        if (candidates.size() == expected) {
            return candidates;
        }
    } catch (const std::exception&) {
        // A damaged or foreign file under our name: measure again.
    }
    return std::nullopt;
}

void writeTable(const std::filesystem::path& path, const scene::Scene& scene,
                const CalibrationRequest& request, const std::vector<AutoCandidate>& candidates) {
    nlohmann::ordered_json json = {{"scene", scene.name},
                                   {"commit", std::string(gitCommit())},
                                   {"width", request.width},
                                   {"height", request.height},
                                   {"frames", request.frames},
                                   {"reference_spp", request.referenceSpp},
                                   {"candidates", nlohmann::ordered_json::array()}};
    for (const AutoCandidate& c : candidates) {
        json["candidates"].push_back({{"technique", c.technique},
                                      {"preset", c.preset},
                                      {"frame_ms", c.frameMs},
                                      {"relmse", c.relMse}});
    }
    std::filesystem::create_directories(path.parent_path());
    // Under a name of this process's own, renamed into place: never a torn table.
    const std::filesystem::path partial = path.string() + ".partial" + std::to_string(std::random_device{}());
    {
        std::ofstream out(partial);
        out << json.dump(2) << '\n';
        if (!out) {
            throw std::runtime_error("cannot write '" + partial.string() + "'");
        }
    }
    std::filesystem::rename(partial, path);
}

} // namespace

std::filesystem::path defaultCalibrationDirectory() {
    return cacheRoot() / "calibration";
}

std::filesystem::path calibrationPath(const std::filesystem::path& directory, const scene::Scene& scene,
                                      const CalibrationRequest& request) {
    char name[256];
    std::snprintf(name, sizeof(name), "%s_%ux%u_%uf_%uspp_%016llx.json", scene.name.c_str(), request.width,
                  request.height, request.frames, request.referenceSpp,
                  static_cast<unsigned long long>(calibrationKey(scene, request)));
    return directory / name;
}

Calibration loadOrCalibrate(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                            const CalibrationRequest& request, const std::filesystem::path& directory,
                            const std::filesystem::path& referenceDirectory,
                            const std::function<void(const AutoCandidate&)>& measured) {
    Calibration calibration{.path = calibrationPath(directory, scene, request)};
    const size_t expected = request.techniques.size() * request.presets.size();
    if (auto table = readTable(calibration.path, expected)) {
        calibration.candidates = std::move(*table);
        calibration.reused = true;
        return calibration;
    }
    const Reference reference = loadOrRenderReference(
        device, pipelines, scene,
        {.width = request.width, .height = request.height, .spp = request.referenceSpp}, referenceDirectory);
    const RunRequest run{
        .width = request.width, .height = request.height, .frames = request.frames, .seed = kCalibrationSeed};
    for (const std::string& technique : request.techniques) {
        for (const std::string& preset : request.presets) {
            const TechniqueRun result =
                runRealTime(device, pipelines, scene, parseGiTechnique(technique), preset, run, reference);
            calibration.candidates.push_back(
                {technique, preset, result.frameMs, result.checkpoints.back().relMse});
            if (measured) {
                measured(calibration.candidates.back());
            }
        }
    }
    writeTable(calibration.path, scene, request, calibration.candidates);
    return calibration;
}

std::optional<size_t> cheapestUnder(const std::vector<AutoCandidate>& candidates, double budget) {
    std::optional<size_t> best;
    for (size_t i = 0; i < candidates.size(); ++i) {
        if (candidates[i].relMse <= budget && (!best || candidates[i].frameMs < candidates[*best].frameMs)) {
            best = i;
        }
    }
    return best;
}

} // namespace lumina::gi
