#pragma once
// The GPU memory of the screen-probe gather: every intermediate of every pass, kept so that each
// can be read back (tests, --dump-buffers), and the ping-pong pairs of what survives a frame
// (probes, probe radiance history, the full-resolution result and the positions it was made at).
// Layouts in docs/screen_probes.md.
#include "gi/screen_probes/screen_probe_settings.h"
#include "rhi/rhi.h"

#include <array>
#include <cstdint>

namespace lumina::gi {

struct ScreenProbeResources {
    uint32_t width = 0, height = 0;         // full resolution
    uint32_t gridWidth = 0, gridHeight = 0; // the uniform grid's probes across and down
    // Probe slots: the uniform grid's (gridWidth x gridHeight), then adaptiveRows rows of gridWidth
    // adaptive slots below it. Every per-probe buffer and the irradiance atlas hold probeCount.
    uint32_t uniformProbeCount = 0;
    uint32_t adaptiveRows = 0;
    uint32_t probeCount = 0;
    // Adaptive tiles: adaptiveSpacing (probeSpacing / 2) pixels a side, adaptiveWidth x adaptiveHeight
    // of them; all 0 when adaptive probes are off.
    uint32_t adaptiveSpacing = 0, adaptiveWidth = 0, adaptiveHeight = 0, adaptiveRunsPerRow = 0;
    uint32_t probeRows() const { return gridHeight + adaptiveRows; }
    uint32_t raysPerProbe = 0;

    rhi::BufferHandle constants;             // ScreenProbeConstants
    std::array<rhi::BufferHandle, 2> probes; // ScreenProbe[probeCount], this frame's and last frame's
    // Adaptive placement, per adaptive tile (at least 1 entry each): the pixel that wants a probe
    // (packAdaptivePixel) or LUMINA_SP_NO_ADAPTIVE_PROBE; per run of LUMINA_SP_ADAPTIVE_RUN tiles of
    // a row (adaptiveRunsPerRow a row), how many want one; the number wanted in the whole image
    // (uint[1]).
    rhi::BufferHandle adaptiveCandidates, adaptiveRunWanted, adaptiveWanted;
    // uint per adaptive tile: its probe's slot or LUMINA_SP_NO_ADAPTIVE_PROBE; last frame's finds the
    // history of adaptive probes.
    std::array<rhi::BufferHandle, 2> adaptiveIndex;
    rhi::BufferHandle brdfPdf;                  // float[probeCount x 64]: texel probabilities
    rhi::BufferHandle lightingPdf;              // float[probeCount x 64]
    rhi::BufferHandle rays;                     // ProbeRay[probeCount x raysPerProbe]
    rhi::BufferHandle hits;                     // SdfHit[probeCount x raysPerProbe]
    rhi::BufferHandle nearField;                // float4[probeCount x raysPerProbe]: near-field radiance, a:
                                                // LUMINA_SP_NEAR_* (written only when the near field runs)
    rhi::BufferHandle rayRadiance;              // float4[probeCount x raysPerProbe]
    rhi::BufferHandle frameRadiance;            // float4[probeCount x 64]: this frame's composite
    std::array<rhi::BufferHandle, 2> history;   // float4[probeCount x 64]: accumulated radiance
    std::array<rhi::BufferHandle, 2> probeAge;  // uint[probeCount]: frames of history (probe_temporal)
    std::array<rhi::BufferHandle, 2> unclamped; // float[probeCount x 64]: the history's luminance before
                                                // the outlier clamp, the clamp's reference
    rhi::BufferHandle filtered;                 // float4[probeCount x 64]: after the spatial filter
    rhi::BufferHandle sh;                       // float4[probeCount x 9]: rgb per SH coefficient
    rhi::TextureHandle irradiance;              // RGBA32F atlas of bordered octahedral tiles
    rhi::TextureHandle gather; // RGBA32F full resolution: irradiance, before the screen filter
    std::array<rhi::TextureHandle, 2> screenIrradiance; // RGBA32F: the result; a: frames accumulated
    std::array<rhi::TextureHandle, 2> screenPosition;   // RGBA32F: GBuffer position the result was made at
    rhi::TextureHandle noVoxelLighting; // 1x1x1 RGBA16F of zeros, bound when the caller has none
    rhi::SamplerHandle linearClamp;

    static ScreenProbeResources create(rhi::IDevice& device, uint32_t width, uint32_t height,
                                       const ScreenProbeSettings& settings);
};

} // namespace lumina::gi
