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

std::ofstream openForWriting(const std::filesystem::path& path) {
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
    std::ofstream out = openForWriting(path);
    out << "scene,technique,preset,width,height,frames,spp_per_frame,frame_ms,relmse_frame1,relmse_converged,"
           "indirect_relmse_frame1,indirect_relmse_converged,flip_converged,frames_to_converge,gpu_memory_"
           "mib,"
           "non_finite_pixels,reference_spp,passes_ms,device,driver,api,commit\n";
    for (const BenchRecord& record : records) {
        const TechniqueRun& run = record.run;
        const Checkpoint& first = run.checkpoints.front();
        const Checkpoint& last = run.checkpoints.back();
        out << csvField(record.scene) << ',' << run.technique << ',' << csvField(run.preset) << ','
            << run.width << ',' << run.height << ',' << run.frames << ',' << run.samplesPerFrame << ','
            << run.frameMs << ',' << first.relMse << ',' << last.relMse << ',' << first.indirectRelMse << ','
            << last.indirectRelMse << ',' << last.flip << ',' << run.framesToConverge << ','
            << mib(run.gpuMemoryBytes) << ',' << run.nonFinitePixels << ',' << context.referenceSpp << ','
            << csvField(passList(run.passes)) << ',' << csvField(context.device) << ','
            << csvField(context.driver) << ',' << context.api << ',' << context.commit << '\n';
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
        nlohmann::ordered_json passes = nlohmann::ordered_json::object();
        for (const PassTiming& pass : run.passes) {
            passes[pass.name] = {{"median_ms", pass.medianMs},
                                 {"min_ms", pass.minMs},
                                 {"max_ms", pass.maxMs},
                                 {"frames", pass.frames}};
        }
        nlohmann::ordered_json checkpoints = nlohmann::ordered_json::array();
        for (const Checkpoint& c : run.checkpoints) {
            checkpoints.push_back({{"frame", c.frame},
                                   {"relmse", c.relMse},
                                   {"indirect_relmse", c.indirectRelMse},
                                   {"flip", c.flip}});
        }
        json["runs"].push_back({{"scene", record.scene},
                                {"technique", run.technique},
                                {"preset", run.preset},
                                {"width", run.width},
                                {"height", run.height},
                                {"frames", run.frames},
                                {"spp_per_frame", run.samplesPerFrame},
                                {"frame_ms", run.frameMs},
                                {"frames_to_converge", run.framesToConverge},
                                {"gpu_memory_bytes", run.gpuMemoryBytes},
                                {"non_finite_pixels", run.nonFinitePixels},
                                {"reference", record.referencePath},
                                {"passes", passes},
                                {"checkpoints", checkpoints}});
    }
    std::ofstream out = openForWriting(path);
    out << json.dump(2) << '\n';
}

} // namespace lumina::gi
