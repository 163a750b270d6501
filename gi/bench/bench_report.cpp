#include "gi/bench/bench_report.h"

#include <chrono>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace lumina::gi {

namespace {

std::ofstream openReportFile(const std::filesystem::path& path) {
    std::ofstream out(path);
    if (!out) {
        throw std::runtime_error("cannot write '" + path.string() + "'");
    }
    out << std::setprecision(9);
    return out;
}

// RFC 4180: a field with a comma, quote or newline is quoted, quotes doubled.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) {
        return text;
    }
    std::string quoted = "\"";
    for (char c : text) {
        quoted += c == '"' ? "\"\"" : std::string(1, c);
    }
    return quoted + "\"";
}

// An absent figure: an empty CSV field.
template <typename T>
std::string optionalField(const std::optional<T>& value) {
    std::ostringstream out;
    out << std::setprecision(9);
    if (value) {
        out << *value;
    }
    return out.str();
}

template <typename T>
nlohmann::ordered_json optionalJson(const std::optional<T>& value) {
    return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json passesJson(const std::vector<PassTiming>& passes) {
    nlohmann::ordered_json json = nlohmann::ordered_json::object();
    for (const PassTiming& pass : passes) {
        json[pass.name] = {{"median_ms", pass.medianMs},
                           {"min_ms", pass.minMs},
                           {"max_ms", pass.maxMs},
                           {"frames", pass.frames}};
    }
    return json;
}

std::string passList(const std::vector<PassTiming>& passes) {
    std::ostringstream out;
    out << std::setprecision(6);
    for (const PassTiming& pass : passes) {
        if (pass.name != "frame") {
            out << (out.tellp() > 0 ? ";" : "") << pass.name << "=" << pass.medianMs;
        }
    }
    return out.str();
}

double mib(uint64_t bytes) {
    return double(bytes) / (1024.0 * 1024.0);
}

} // namespace

std::string utcTimestamp() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
#ifdef _WIN32
    gmtime_s(&utc, &now);
#else
    gmtime_r(&now, &utc);
#endif
    char text[32];
    std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

void writeBenchCsv(const std::filesystem::path& path, const BenchContext& context,
                   const std::vector<BenchRecord>& records) {
    std::ofstream out = openReportFile(path);
    out << "scene,technique,preset,width,height,frames,spp_per_frame,frame_ms,settled_frame_ms,"
           "settled_after_frame,relmse_frame1,relmse_converged,indirect_relmse_frame1,indirect_relmse_"
           "converged,flip_converged,frames_to_converge,gpu_memory_mib,non_finite_pixels,reference_spp,"
           "passes_ms,device,driver,api,commit\n";
    for (const BenchRecord& record : records) {
        const TechniqueRun& run = record.run;
        const Checkpoint& first = run.checkpoints.front();
        const Checkpoint& last = run.checkpoints.back();
        out << csvField(record.scene) << ',' << run.technique << ',' << csvField(run.preset) << ','
            << run.width << ',' << run.height << ',' << run.frames << ',' << run.samplesPerFrame << ','
            << run.frameMs << ',' << optionalField(run.settledFrameMs) << ','
            << optionalField(run.settledAfterFrame) << ',' << first.relMse << ',' << last.relMse << ','
            << first.indirectRelMse << ',' << last.indirectRelMse << ',' << last.flip << ','
            << run.framesToConverge << ',' << mib(run.gpuMemoryBytes) << ',' << run.nonFinitePixels << ','
            << context.referenceSpp << ',' << csvField(passList(run.passes)) << ','
            << csvField(context.device) << ',' << csvField(context.driver) << ',' << context.api << ','
            << context.commit << '\n';
    }
}

void writeBenchJson(const std::filesystem::path& path, const BenchContext& context,
                    const std::vector<BenchRecord>& records) {
    nlohmann::ordered_json json;
    json["context"] = {{"commit", context.commit}, {"device", context.device},
                       {"driver", context.driver}, {"api", context.api},
                       {"date", context.date},     {"reference_spp", context.referenceSpp}};
    json["runs"] = nlohmann::ordered_json::array();
    for (const BenchRecord& record : records) {
        const TechniqueRun& run = record.run;
        nlohmann::ordered_json checkpoints = nlohmann::ordered_json::array();
        for (const Checkpoint& c : run.checkpoints) {
            checkpoints.push_back({{"frame", c.frame},
                                   {"relmse", c.relMse},
                                   {"indirect_relmse", c.indirectRelMse},
                                   {"flip", c.flip}});
        }
        nlohmann::ordered_json entry = {{"scene", record.scene},
                                        {"technique", run.technique},
                                        {"preset", run.preset},
                                        {"width", run.width},
                                        {"height", run.height},
                                        {"frames", run.frames},
                                        {"spp_per_frame", run.samplesPerFrame},
                                        {"frame_ms", run.frameMs},
                                        {"settled_after_frame", optionalJson(run.settledAfterFrame)},
                                        {"settled_frame_ms", optionalJson(run.settledFrameMs)},
                                        {"frames_to_converge", run.framesToConverge},
                                        {"gpu_memory_bytes", run.gpuMemoryBytes},
                                        {"non_finite_pixels", run.nonFinitePixels},
                                        {"reference", record.referencePath},
                                        {"passes", passesJson(run.passes)},
                                        {"settled_passes", passesJson(run.settledPasses)},
                                        {"checkpoints", checkpoints}};
        if (record.budget) {
            entry["budget"] = {{"multiple", record.budget->multiple},
                               {"of", record.budget->base.technique},
                               {"base_ms", record.budget->base.ms}};
        }
        json["runs"].push_back(std::move(entry));
    }
    std::ofstream out = openReportFile(path);
    out << json.dump(2) << '\n';
}

} // namespace lumina::gi
