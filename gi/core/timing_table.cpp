#include "gi/core/timing_table.h"

#include "rhi/error.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>

namespace lumina::gi {

double median(std::vector<double> values) {
    if (values.empty()) {
        return 0.0;
    }
    const size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    if (values.size() % 2 == 1) {
        return values[mid];
    }
    const double upper = values[mid];
    return (*std::max_element(values.begin(), values.begin() + mid) + upper) / 2.0;
}

void TimingTable::addFrame(const std::vector<rhi::TimerResult>& timers,
                           const std::vector<SkippedPass>& skipped) {
    if (seenFrames_++ < warmupFrames_) {
        return;
    }
    ++recordedFrames_;
    std::map<std::string, double> frame;
    double total = 0.0;
    uint64_t lastTopLevelEnd = 0;
    for (const rhi::TimerResult& timer : timers) {
        if (!samples_.contains(timer.name) && !frame.contains(timer.name)) {
            order_.push_back(timer.name);
        }
        frame[timer.name] += timer.milliseconds;
        // Nested regions lie inside an earlier one; only top-level regions add to the total.
        if (timer.beginTicks >= lastTopLevelEnd) {
            total += timer.milliseconds;
            lastTopLevelEnd = timer.endTicks;
        }
    }
    for (const auto& [name, ms] : frame) {
        samples_[name].push_back(ms);
    }
    frameTotals_.push_back(total);
    for (const SkippedPass& skip : skipped) {
        ++skipCounts_[{skip.pass, skip.reason, skip.kind}];
    }
}

std::vector<PassTiming> TimingTable::passes() const {
    std::vector<PassTiming> out;
    for (const std::string& name : order_) {
        const auto& values = samples_.at(name);
        out.push_back({name, median(values), *std::min_element(values.begin(), values.end()),
                       *std::max_element(values.begin(), values.end()), uint32_t(values.size())});
    }
    if (!frameTotals_.empty()) {
        out.push_back(
            {"frame", median(frameTotals_), *std::min_element(frameTotals_.begin(), frameTotals_.end()),
             *std::max_element(frameTotals_.begin(), frameTotals_.end()), uint32_t(frameTotals_.size())});
    }
    return out;
}

std::vector<SkipCount> TimingTable::skips() const {
    std::vector<SkipCount> out;
    for (const auto& [key, count] : skipCounts_) {
        const auto& [pass, reason, kind] = key;
        out.push_back({pass, reason, count, kind});
    }
    return out;
}

double TimingTable::medianFrameMs() const {
    return median(frameTotals_);
}

void TimingTable::print(std::ostream& out) const {
    out << "GPU time per pass over " << recordedFrames_ << " frame(s) after " << warmupFrames_
        << " warm-up:\n";
    out << std::left << std::setw(40) << "  pass" << std::right << std::setw(11) << "median ms"
        << std::setw(11) << "min ms" << std::setw(11) << "max ms" << std::setw(8) << "runs" << '\n';
    out << std::fixed << std::setprecision(4);
    for (const PassTiming& pass : passes()) {
        out << "  " << std::left << std::setw(38) << pass.name << std::right << std::setw(11) << pass.medianMs
            << std::setw(11) << pass.minMs << std::setw(11) << pass.maxMs << std::setw(8) << pass.frames
            << '\n';
    }
    out << std::defaultfloat;
    for (const SkipCount& skip : skips()) {
        out << "  " << skip.pass << ": skipped in " << skip.frames << " frame(s), " << skip.reason << '\n';
    }
}

void TimingTable::writeJson(const std::filesystem::path& path,
                            const std::map<std::string, std::string>& context) const {
    nlohmann::json root;
    for (const auto& [key, value] : context) {
        root["context"][key] = value;
    }
    root["warmupFrames"] = warmupFrames_;
    root["frames"] = recordedFrames_;
    for (const PassTiming& pass : passes()) {
        root["passes"].push_back({{"name", pass.name},
                                  {"medianMs", pass.medianMs},
                                  {"minMs", pass.minMs},
                                  {"maxMs", pass.maxMs},
                                  {"runs", pass.frames}});
    }
    for (const SkipCount& skip : skips()) {
        root["skipped"].push_back({{"pass", skip.pass},
                                   {"reason", skip.reason},
                                   {"kind", skip.kind == SkipKind::Reuse ? "reuse" : "nothing to run"},
                                   {"frames", skip.frames}});
    }
    std::ofstream file(path);
    if (!file) {
        throw rhi::Error("cannot write timings to " + path.string());
    }
    file << root.dump(2) << '\n';
}

} // namespace lumina::gi
