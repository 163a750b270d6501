#include "gi/ddgi/ddgi_resources.h"

#include "gi/core/gpu_resources.h"

#include <stdexcept>
#include <string>

namespace lumina::gi {

DdgiResources DdgiResources::create(rhi::IDevice& device, const DdgiAtlasLayout& layout,
                                    uint32_t raysPerProbe, uint32_t width, uint32_t height) {
    if (width == 0 || height == 0) {
        throw std::invalid_argument("ddgi: image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " (expected both > 0)");
    }
    DdgiResources r;
    r.layout = layout;
    r.raysPerProbe = raysPerProbe;
    r.width = width;
    r.height = height;
    r.constants = device.createBuffer({.size = sizeof(gpu::DdgiConstants),
                                       .usage = rhi::BufferUsage::Constant,
                                       .debugName = "ddgi: constants"});
    r.probes = createStructuredBuffer(device, layout.probes, sizeof(gpu::DdgiProbe), "ddgi: probes");
    r.rayData = createStructuredBuffer(device, uint64_t(layout.probes) * raysPerProbe, sizeof(gpu::float4),
                                       "ddgi: ray data");
    r.irradiance = createStorageTexture2d(device, rhi::Format::RGBA16_FLOAT, r.irradianceWidth(),
                                          r.irradianceHeight(), "ddgi: irradiance atlas");
    r.distance = createStorageTexture2d(device, rhi::Format::RG16_FLOAT, r.distanceWidth(),
                                        r.distanceHeight(), "ddgi: distance atlas");
    r.sampled = createStorageTexture2d(device, rhi::Format::RGBA16_FLOAT, width, height, "ddgi: irradiance");
    r.linearClamp = device.createSampler({.debugName = "ddgi: linear clamp"});
    return r;
}

} // namespace lumina::gi
