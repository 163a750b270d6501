#pragma once
// Quality settings of the screen-probe final gather, in one struct (docs/screen_probes.md).
// validate() throws std::invalid_argument naming the first bad value.
#include <cstdint>
#include <optional>

namespace lumina::gi {

// The ranges validate() accepts, named once for the CLI and the viewer.
inline constexpr uint32_t kMinProbeSpacing = 2;  // pixels
inline constexpr uint32_t kMaxProbeSpacing = 64; // pixels
inline constexpr uint32_t kMinRaysPerProbe = 16;
inline constexpr uint32_t kMaxRaysPerProbe = 256; // LUMINA_SP_MAX_RAYS

struct ScreenProbeSettings {
    uint32_t probeSpacing = 8; // pixels per probe edge: one probe per spacing x spacing pixels
    // Room for adaptive probes (probe_adaptive_placement.hlsl), as a share of the uniform grid's
    // probes (0 .. 1; 0: none). They go where a pixel lies on no uniform probe's surface, at most one
    // per (probeSpacing / 2)^2 pixels; only those placed cost rays. At 128 x 128 a quarter holds what
    // the boxes, the rooms and the door want; the engine wants 157 and the atrium 387 for 64 slots,
    // and the tiles past the last slot go without (`lumina render` prints it; docs/screen_probes.md).
    float adaptiveProbeFraction = 0.25f;
    uint32_t raysPerProbe = 64;   // 16 .. 256
    float brdfRayFraction = 0.5f; // share of the rays drawn from the BRDF PDF; the rest from the lighting PDF
    float lightingPdfFloor = 0.1f; // share of the lighting PDF spread uniformly over the hemisphere, so
                                   // every direction stays reachable (0 < floor <= 1)

    float maxTraceDistance = 0.0f; // world units; 0: the global SDF grid's diagonal
    // Far-field cone, radians. A cone stops where the SDF falls below its radius, so a wide one
    // stops at every edge it passes near: with the thesis's 0.1 (50 mm wide at 500 mm in the Cornell
    // box) the blocks' edges shadowed half the floor's rays to the light (floor at 55% of the
    // path tracer's, 77% with 0.02; docs/screen_probes.md).
    float coneHalfAngle = 0.02f;
    float originBiasVoxels = 2.0f; // rays start this many global SDF voxels off the surface, along its normal
    // Rays are traced through the mesh SDFs (reading the surface cache at hits) up to this distance
    // and through the global SDF beyond. World units; 0: no near field; unset:
    // kNearFieldGridFraction x the global SDF grid's diagonal. Capped at the trace distance; needs a
    // surface cache among the inputs.
    std::optional<float> nearFieldDistance;
    // A quarter of the diagonal (300 mm in the Cornell box): there the cone is 2.5% of the diagonal
    // wide and its hits lie about that far in front of their surfaces; nearer, the card texels are
    // worth their cost. In the Cornell box, the near field at this distance takes about as long as the
    // far field it replaces and brings the gather's mean from 57% to 80% of the path tracer's
    // (the surface cache's own: 76%; docs/screen_probes.md).
    static constexpr float kNearFieldGridFraction = 0.25f;
    // A near field longer than any trace: every ray a mesh-SDF trace read from the cards, the far
    // field skipped (medium's and high's since docs/gi.md, energy 41.).
    static constexpr float kNearFieldWholeTrace = 1e30f;

    float probeHistoryBlend = 0.1f; // weight of the new frame in the probe radiance history
    // New radiance is clamped to the factor 1 + (outlierClamp - 1) / (rays a texel) times
    // max(outlierClampTexelShare x the texel's unclamped mean, the probe's mean of them)
    // (probe_temporal.hlsl). The share is a bias knob like outlierClamp itself, measured against
    // the references (docs/gi.md, energy 40. and 41.): at 1 cornell_box read 3.0 % bright at high on
    // the H200 (256^2), at 0.5 sunlit_rooms 3.0 % dark at low.
    float outlierClamp = 4.0f;
    float outlierClampTexelShare = 0.6f;
    float historyPlaneTolerance = 0.02f; // history kept while the old probe lies this close (x view depth)
                                         // to the new one's plane
    float historyNormalTolerance = 0.9f; // ... and their normals' cosine is at least this

    float filterPlaneScale = 0.02f; // spatial filter and gather: exp(-plane distance / (this x view depth))
    float filterNormalPower = 8.0f; // ... times max(0, n . n')^power

    float screenHistoryBlend = 0.2f; // weight of the new frame in the full-resolution temporal filter

    void validate() const;
};

} // namespace lumina::gi
