#include "gi/screen_probes/screen_probe_readback.h"

#include "gi/deferred/buffer_readback.h"
#include "gi/image/exr.h"
#include "shaders/common/sdf_scene_shared.h"
#include "shaders/screen_probes/screen_probe_shared.h"

#include <string>

namespace lumina::gi {

namespace {

// One tile of `tileWidth` x `tileHeight` entries per probe; entry i of probe p at (i % tileWidth,
// i / tileWidth) of p's tile.
template <typename Set>
image::Image tiled(uint32_t perProbe, uint32_t tileWidth, uint32_t gridWidth, uint32_t gridHeight,
                   std::vector<std::string> channels, Set set) {
    const uint32_t tileHeight = (perProbe + tileWidth - 1) / tileWidth;
    image::Image out(gridWidth * tileWidth, gridHeight * tileHeight, std::move(channels));
    for (uint32_t p = 0; p < gridWidth * gridHeight; ++p) {
        for (uint32_t i = 0; i < perProbe; ++i) {
            set(out, (p % gridWidth) * tileWidth + i % tileWidth,
                (p / gridWidth) * tileHeight + i / tileWidth, size_t(p) * perProbe + i);
        }
    }
    return out;
}

void setRgba(image::Image& image, uint32_t x, uint32_t y, const gpu::float4& v) {
    image.set("R", x, y, v.x);
    image.set("G", x, y, v.y);
    image.set("B", x, y, v.z);
    image.set("A", x, y, v.w);
}

} // namespace

image::Image probeMapImage(std::span<const gpu::float4> texels, uint32_t gridWidth, uint32_t gridHeight) {
    return tiled(
        LUMINA_SP_PROBE_TEXELS, LUMINA_SP_OCT_SIZE, gridWidth, gridHeight, {"R", "G", "B", "A"},
        [&](image::Image& image, uint32_t x, uint32_t y, size_t i) { setRgba(image, x, y, texels[i]); });
}

image::Image probeTableImage(std::span<const float> texels, uint32_t gridWidth, uint32_t gridHeight) {
    return tiled(LUMINA_SP_PROBE_TEXELS, LUMINA_SP_OCT_SIZE, gridWidth, gridHeight, {"R", "G", "B"},
                 [&](image::Image& image, uint32_t x, uint32_t y, size_t i) {
                     image.setRgb(x, y, {texels[i], texels[i], texels[i]});
                 });
}

image::Image probeRayImage(std::span<const gpu::float4> rays, uint32_t raysPerProbe, uint32_t gridWidth,
                           uint32_t gridHeight) {
    return tiled(
        raysPerProbe, LUMINA_SP_OCT_SIZE, gridWidth, gridHeight, {"R", "G", "B", "A"},
        [&](image::Image& image, uint32_t x, uint32_t y, size_t i) { setRgba(image, x, y, rays[i]); });
}

std::vector<std::filesystem::path> dumpScreenProbeBuffers(rhi::IDevice& device,
                                                          const ScreenProbeGather& gather,
                                                          const std::filesystem::path& directory) {
    std::filesystem::create_directories(directory);
    const ScreenProbeResources& r = gather.resources();
    const uint32_t gw = r.gridWidth, gh = r.probeRows(), current = gather.current();
    std::vector<std::filesystem::path> written;
    auto exr = [&](const std::string& name, const image::Image& image) {
        written.push_back(directory / ("screen_probes_" + name + ".exr"));
        image::writeExr(written.back(), image);
    };
    auto float4s = [&](const rhi::BufferHandle& buffer) {
        return rhi::readBufferAs<gpu::float4>(device, *buffer);
    };

    const auto probes = rhi::readBufferAs<gpu::ScreenProbe>(device, *r.probes[current]);
    image::Image position(gw, gh, {"R", "G", "B", "A"}), normal(gw, gh, {"R", "G", "B", "A"});
    for (uint32_t p = 0; p < probes.size(); ++p) {
        setRgba(position, p % gw, p / gw, probes[p].positionAndDepth);
        setRgba(normal, p % gw, p / gw, gpu::float4(gpu::float3(probes[p].normal), float(probes[p].info.x)));
    }
    exr("probe_position", position);
    exr("probe_normal", normal);
    exr("brdf_pdf", probeTableImage(rhi::readBufferAs<float>(device, *r.brdfPdf), gw, gh));
    exr("lighting_pdf", probeTableImage(rhi::readBufferAs<float>(device, *r.lightingPdf), gw, gh));

    const auto rays = rhi::readBufferAs<gpu::ProbeRay>(device, *r.rays);
    const auto hits = rhi::readBufferAs<gpu::SdfHit>(device, *r.hits);
    std::vector<gpu::float4> directions, records, hitPoints;
    for (size_t i = 0; i < rays.size(); ++i) {
        directions.push_back(rays[i].directionAndWeight);
        hitPoints.push_back(hits[i].positionAndT);
        records.emplace_back(hits[i].positionAndT.w, float(hits[i].ids.z), float(hits[i].ids.w),
                             hits[i].normalAndCoverage.w);
    }
    exr("ray_directions", probeRayImage(directions, r.raysPerProbe, gw, gh));
    exr("ray_hits", probeRayImage(records, r.raysPerProbe, gw, gh));
    exr("ray_hit_points", probeRayImage(hitPoints, r.raysPerProbe, gw, gh)); // world position, t
    if (gather.nearFieldTraced()) {
        exr("near_field", probeRayImage(float4s(r.nearField), r.raysPerProbe, gw, gh));
    }
    exr("ray_radiance", probeRayImage(float4s(r.rayRadiance), r.raysPerProbe, gw, gh));
    exr("frame_radiance", probeMapImage(float4s(r.frameRadiance), gw, gh));
    exr("history", probeMapImage(float4s(r.history[current]), gw, gh));
    exr("filtered", probeMapImage(float4s(r.filtered), gw, gh));

    const auto sh = float4s(r.sh);
    image::Image shImage(gw * LUMINA_SH_COEFFICIENTS, gh, {"R", "G", "B"});
    for (uint32_t p = 0; p < gw * gh; ++p) {
        for (uint32_t k = 0; k < LUMINA_SH_COEFFICIENTS; ++k) {
            const gpu::float4& c = sh[p * LUMINA_SH_COEFFICIENTS + k];
            shImage.setRgb((p % gw) * LUMINA_SH_COEFFICIENTS + k, p / gw, {c.x, c.y, c.z});
        }
    }
    exr("sh", shImage);
    exr("irradiance_atlas", readTextureImage(device, *r.irradiance));
    exr("gather", readTextureImage(device, *r.gather));
    exr("screen_irradiance", readTextureImage(device, *r.screenIrradiance[current]));
    return written;
}

} // namespace lumina::gi
