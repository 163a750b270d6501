#include "gi/sh_grid/sh_grid_resources.h"

#include "gi/core/gpu_resources.h"
#include "shaders/sh_grid/sh_grid_shared.h"

#include <stdexcept>
#include <string>

namespace lumina::gi {

ShGridResources ShGridResources::create(rhi::IDevice& device, const ShGridLayout& layout, uint32_t width,
                                        uint32_t height) {
    if (width == 0 || height == 0) {
        throw std::invalid_argument("sh-grid: image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " (expected both > 0)");
    }
    ShGridResources r;
    r.layout = layout;
    r.width = width;
    r.height = height;
    r.constants = device.createBuffer({.size = sizeof(gpu::ShGridConstants),
                                       .usage = rhi::BufferUsage::Constant,
                                       .debugName = "sh grid: constants"});
    r.coefficients = createStructuredBuffer(device, uint64_t(layout.probes()) * LUMINA_SH_GRID_COEFFICIENTS,
                                            sizeof(gpu::float4), "sh grid: coefficients");
    r.bounceSource = createStructuredBuffer(device, uint64_t(layout.probes()) * LUMINA_SH_GRID_COEFFICIENTS,
                                            sizeof(gpu::float4), "sh grid: bounce source");
    r.partials = createStructuredBuffer(device, LUMINA_SH_GRID_FACES * LUMINA_SH_GRID_COEFFICIENTS,
                                        sizeof(gpu::float4), "sh grid: face projections");
    r.sampled =
        createStorageTexture2d(device, rhi::Format::RGBA16_FLOAT, width, height, "sh grid: irradiance");
    return r;
}

} // namespace lumina::gi
