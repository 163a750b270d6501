#pragma once
// The GPU memory of the SH probe grid (docs/sh_grid.md): every probe's nine irradiance
// coefficients, the partial projections of the probe being baked, the constants the kernels
// read and the per-pixel irradiance the composite reads.
#include "gi/sh_grid/sh_grid_settings.h"
#include "rhi/rhi.h"

#include <cstdint>

namespace lumina::gi {

struct ShGridResources {
    ShGridLayout layout;
    uint32_t width = 0, height = 0;

    rhi::BufferHandle constants;    // ShGridConstants
    rhi::BufferHandle coefficients; // float4[probes x 9]: rgb irradiance coefficients (sh_grid_shared.h)
    rhi::BufferHandle bounceSource; // the same, as the sweep under way began: what its bounces read
    rhi::BufferHandle partials;     // float4[6 faces x 9]: one face's projection each
    rhi::TextureHandle sampled;     // RGBA16F width x height: irradiance E per pixel

    // std::invalid_argument for an empty image.
    static ShGridResources create(rhi::IDevice& device, const ShGridLayout& layout, uint32_t width,
                                  uint32_t height);
};

} // namespace lumina::gi
