#include "tests/frame/probe_health.h"

#include "gi/measure/metrics.h"
#include "rhi/transfer.h"
#include "shaders/screen_probes/screen_probe_shared.h"

#include <cmath>

namespace lumina::test {

namespace {

bool finite(const gpu::float4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

} // namespace

ProbeHealth probeHealth(rhi::IDevice& device, FrameHarness& h) {
    const gi::ScreenProbeGather& gather = h.lumen().screenProbes();
    const gi::ScreenProbeResources& r = gather.resources();
    const auto probes = rhi::readBufferAs<gpu::ScreenProbe>(device, *r.probes[gather.current()]);
    const auto history = rhi::readBufferAs<gpu::float4>(device, *r.history[gather.current()]);
    const image::Image atlas = h.read(r.irradiance);
    ProbeHealth health;
    for (uint32_t p = 0; p < r.probeCount; ++p) {
        if (probes[p].info.x != LUMINA_SP_PROBE_VALID) {
            continue;
        }
        ++health.validProbes;
        for (uint32_t t = 0; t < LUMINA_SP_PROBE_TEXELS; ++t) {
            health.nonFiniteHistory += finite(history[size_t(p) * LUMINA_SP_PROBE_TEXELS + t]) ? 0 : 1;
        }
        const uint32_t tileX = (p % r.gridWidth) * LUMINA_SP_IRRADIANCE_TILE;
        const uint32_t tileY = (p / r.gridWidth) * LUMINA_SP_IRRADIANCE_TILE;
        for (uint32_t y = tileY; y < tileY + LUMINA_SP_IRRADIANCE_TILE; ++y) {
            for (uint32_t x = tileX; x < tileX + LUMINA_SP_IRRADIANCE_TILE; ++x) {
                const image::Rgb e = atlas.rgbAt(x, y);
                health.nonFiniteIrradiance += std::isfinite(e.r + e.g + e.b) ? 0 : 1;
            }
        }
    }
    health.nonFiniteScreen = measure::countNonFinite(h.read(h.renderer().indirect())).total();
    return health;
}

} // namespace lumina::test
