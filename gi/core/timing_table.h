#pragma once
// Per-pass GPU time over many frames: median, min and max after a warm-up, plus how often
// each pass was skipped and why. Printed by `--timings`, written by `--timings-json`.
#include "gi/core/frame_context.h"
#include "rhi/command_list.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

namespace lumina::gi {

struct PassTiming {
    std::string name;
    double medianMs = 0;
    double minMs = 0;
    double maxMs = 0;
    uint32_t frames = 0; // frames the pass ran in (after warm-up)
};

struct SkipCount {
    std::string pass;
    std::string reason;
    uint32_t frames = 0;
    SkipKind kind = SkipKind::NothingToRun;
};

class TimingTable {
public:
    explicit TimingTable(uint32_t warmupFrames = 0) : warmupFrames_(warmupFrames) {}

    // One frame's timer results (a pass timed twice in a frame counts once, summed) and skips.
    void addFrame(const std::vector<rhi::TimerResult>& timers, const std::vector<SkippedPass>& skipped = {});

    // In first-seen order; "frame" (the sum of top-level passes) last.
    std::vector<PassTiming> passes() const;
    std::vector<SkipCount> skips() const;
    double medianFrameMs() const;
    // Each recorded frame's total (the sum of its top-level passes), in order.
    const std::vector<double>& frameTotals() const { return frameTotals_; }
    // The sum of the top-level passes of the last frame added; 0 before any.
    double lastFrameMs() const { return frameTotals_.empty() ? 0.0 : frameTotals_.back(); }
    uint32_t recordedFrames() const { return recordedFrames_; }

    void print(std::ostream& out) const;
    // Context (device, driver, API, commit, scene) goes in as key/value pairs.
    void writeJson(const std::filesystem::path& path,
                   const std::map<std::string, std::string>& context) const;

private:
    uint32_t warmupFrames_;
    uint32_t seenFrames_ = 0;
    uint32_t recordedFrames_ = 0;
    std::vector<std::string> order_;
    std::map<std::string, std::vector<double>> samples_;
    std::vector<double> frameTotals_;
    std::map<std::tuple<std::string, std::string, SkipKind>, uint32_t> skipCounts_;
};

double median(std::vector<double> values);

} // namespace lumina::gi
