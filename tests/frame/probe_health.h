#pragma once
// Whether the screen probes hold only finite values where they are meaningful, for the
// long-running tests (docs/gi_tests.md).
#include "tests/frame/frame_harness.h"

#include <cstdint>

namespace lumina::test {

// Non-finite values the screen probes hold where they are meaningful: the valid probes' radiance
// history and irradiance tiles (invalid probes' entries are never written), and every pixel of
// the screen irradiance.
struct ProbeHealth {
    uint32_t validProbes = 0;
    uint64_t nonFiniteHistory = 0;
    uint64_t nonFiniteIrradiance = 0;
    uint64_t nonFiniteScreen = 0;
};

// After the last frame `h` rendered (the lumen technique).
ProbeHealth probeHealth(rhi::IDevice& device, FrameHarness& h);

} // namespace lumina::test
