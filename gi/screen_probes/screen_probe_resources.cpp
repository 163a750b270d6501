#include "gi/screen_probes/screen_probe_resources.h"

#include "gi/core/gpu_resources.h"
#include "shaders/common/sdf_scene_shared.h"
#include "shaders/screen_probes/screen_probe_shared.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

rhi::BufferHandle structured(rhi::IDevice& device, uint64_t count, uint32_t stride, const std::string& name) {
    return createStructuredBuffer(device, count, stride, "screen probes: " + name);
}

rhi::TextureHandle storage2d(rhi::IDevice& device, rhi::Format format, uint32_t width, uint32_t height,
                             const std::string& name) {
    return createStorageTexture2d(device, format, width, height, "screen probes: " + name);
}

} // namespace

ScreenProbeResources ScreenProbeResources::create(rhi::IDevice& device, uint32_t width, uint32_t height,
                                                  const ScreenProbeSettings& settings) {
    settings.validate();
    if (width == 0 || height == 0 || width >= 65536 || height >= 65536) {
        // Adaptive placement packs a pixel's coordinates into 16 bits each.
        throw std::invalid_argument("screen probes: image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " (expected both 1 .. 65535)");
    }
    ScreenProbeResources r;
    r.width = width;
    r.height = height;
    r.gridWidth = (width + settings.probeSpacing - 1) / settings.probeSpacing;
    r.gridHeight = (height + settings.probeSpacing - 1) / settings.probeSpacing;
    r.uniformProbeCount = r.gridWidth * r.gridHeight;
    if (settings.adaptiveProbeFraction > 0.0f) {
        r.adaptiveRows = uint32_t(std::ceil(float(r.gridHeight) * settings.adaptiveProbeFraction));
        r.adaptiveSpacing = std::max(settings.probeSpacing / 2, 1u);
        r.adaptiveWidth = (width + r.adaptiveSpacing - 1) / r.adaptiveSpacing;
        r.adaptiveHeight = (height + r.adaptiveSpacing - 1) / r.adaptiveSpacing;
        r.adaptiveRunsPerRow = (r.adaptiveWidth + LUMINA_SP_ADAPTIVE_RUN - 1) / LUMINA_SP_ADAPTIVE_RUN;
    }
    r.probeCount = r.gridWidth * r.probeRows();
    r.raysPerProbe = settings.raysPerProbe;
    const uint64_t texels = uint64_t(r.probeCount) * LUMINA_SP_PROBE_TEXELS;
    const uint64_t rays = uint64_t(r.probeCount) * r.raysPerProbe;

    r.constants = device.createBuffer({.size = sizeof(gpu::ScreenProbeConstants),
                                       .usage = rhi::BufferUsage::Constant,
                                       .debugName = "screen probes: constants"});
    for (uint32_t i = 0; i < 2; ++i) {
        const std::string half = i == 0 ? " A" : " B";
        r.probes[i] = structured(device, r.probeCount, sizeof(gpu::ScreenProbe), "probes" + half);
        r.history[i] = structured(device, texels, sizeof(gpu::float4), "radiance history" + half);
        r.probeAge[i] = structured(device, r.probeCount, sizeof(uint32_t), "probe age" + half);
        r.unclamped[i] = structured(device, texels, sizeof(float), "unclamped luminance" + half);
        r.adaptiveIndex[i] =
            structured(device, std::max(uint64_t(r.adaptiveWidth) * r.adaptiveHeight, uint64_t(1)),
                       sizeof(uint32_t), "adaptive index" + half);
        r.screenIrradiance[i] =
            storage2d(device, rhi::Format::RGBA32_FLOAT, width, height, "screen irradiance" + half);
        r.screenPosition[i] =
            storage2d(device, rhi::Format::RGBA32_FLOAT, width, height, "screen position" + half);
    }
    const uint64_t tiles = std::max(uint64_t(r.adaptiveWidth) * r.adaptiveHeight, uint64_t(1));
    r.adaptiveCandidates = structured(device, tiles, sizeof(uint32_t), "adaptive candidates");
    r.adaptiveRunWanted =
        structured(device, std::max(uint64_t(r.adaptiveRunsPerRow) * r.adaptiveHeight, uint64_t(1)),
                   sizeof(uint32_t), "adaptive runs");
    r.adaptiveWanted = structured(device, 1, sizeof(uint32_t), "adaptive wanted");
    r.brdfPdf = structured(device, texels, sizeof(float), "brdf pdf");
    r.lightingPdf = structured(device, texels, sizeof(float), "lighting pdf");
    r.rays = structured(device, rays, sizeof(gpu::ProbeRay), "rays");
    r.hits = structured(device, rays, sizeof(gpu::SdfHit), "hits");
    r.nearField = structured(device, rays, sizeof(gpu::float4), "near field");
    r.rayRadiance = structured(device, rays, sizeof(gpu::float4), "ray radiance");
    r.frameRadiance = structured(device, texels, sizeof(gpu::float4), "frame radiance");
    r.filtered = structured(device, texels, sizeof(gpu::float4), "filtered radiance");
    r.sh = structured(device, uint64_t(r.probeCount) * LUMINA_SH_COEFFICIENTS, sizeof(gpu::float4), "sh");
    r.irradiance = storage2d(device, rhi::Format::RGBA32_FLOAT, r.gridWidth * LUMINA_SP_IRRADIANCE_TILE,
                             r.probeRows() * LUMINA_SP_IRRADIANCE_TILE, "irradiance atlas");
    r.gather = storage2d(device, rhi::Format::RGBA32_FLOAT, width, height, "gather");
    r.noVoxelLighting = device.createTexture({.dimension = rhi::TextureDimension::Texture3D,
                                              .format = rhi::Format::RGBA16_FLOAT,
                                              .usage = rhi::TextureUsage::Sampled,
                                              .debugName = "screen probes: no voxel lighting"});
    r.linearClamp = device.createSampler({.debugName = "screen probes: linear clamp"});
    return r;
}

} // namespace lumina::gi
