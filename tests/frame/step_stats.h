#pragma once
// The frame-to-frame change of a long run (the dynamic stress and long-run tests): mean and
// largest step, and the frame where the largest happened.
#include <cstdint>

namespace lumina::test {

struct StepStats {
    double sum = 0.0;
    double max = 0.0;
    uint32_t count = 0;
    uint32_t maxFrame = 0;

    void add(double step, uint32_t frame) {
        sum += step;
        ++count;
        if (step > max) {
            max = step;
            maxFrame = frame;
        }
    }
    double mean() const { return count ? sum / count : 0.0; }
};

} // namespace lumina::test
