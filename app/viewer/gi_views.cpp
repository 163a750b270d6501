// The lumen technique's debug views: what the SDFs, the surface cache and the screen probes
// hold this frame, listed for the view menu and visualised by shaders/viewer/visualise_sdf.hlsl,
// visualise_cards.hlsl, visualise_lighting.hlsl, visualise_screen_probes.hlsl and visualise.hlsl.
#include "app/viewer/buffer_views.h"
#include "gi/surface_cache/surface_cache_atlas.h"
#include "shaders/surface_cache/surface_cache_lighting_shared.h"

#include <algorithm>
#include <cmath>

namespace lumina::app::viewer {

namespace {

using Source = BufferView::Source;

// Screen-probe maps hold 8 x 8 octahedral texels per probe (LUMINA_SP_OCT_SIZE); rays are tiled
// 8 wide likewise.
constexpr uint32_t kProbeTile = 8;
constexpr uint32_t kProbeTexels = kProbeTile * kProbeTile;
// PDF tables: uniform is 1/64 per texel; 4x uniform shows as white.
constexpr float kPdfDisplayMax = 4.0f / float(kProbeTexels);
// Slice images get whole texels per voxel until their longer side reaches this, so that the
// SDF's level lines and the voxels stay visible when the window scales the image.
constexpr uint32_t kSliceMinTexels = 256;
// The cone-traced SDF view's half-angle (radians), the one `lumina sdf` traces with.
constexpr float kConeHalfAngle = 0.1f;
// The voxel-lighting slice shows the six faces as three panes across and two down.
constexpr uint32_t kVoxelPanesAcross = 3, kVoxelPanesDown = 2;

BufferView giView(std::string name, Source source, uint32_t mode = LUMINA_VISUALISE_COLOR) {
    BufferView view;
    view.name = std::move(name);
    view.source = source;
    view.mode = mode;
    return view;
}

uint32_t sliceAcross(uint32_t axis) {
    return axis == LUMINA_VISUALISE_AXIS_X ? 2 : 0;
}
uint32_t sliceUp(uint32_t axis) {
    return axis == LUMINA_VISUALISE_AXIS_Y ? 2 : 1;
}

// The slice constants for the box [boxMin, boxMax] of `dims` voxels; returns the image size for
// `panes` copies of the slice side by side.
glm::uvec2 layOutSlice(gpu::VisualiseConstants& constants, const SliceSettings& slice, glm::vec3 boxMin,
                       glm::vec3 boxMax, glm::uvec3 dims, glm::uvec2 panes) {
    constants.sliceAxis = slice.axis;
    constants.sliceMin = boxMin;
    constants.slicePosition = slice.position;
    constants.sliceMax = boxMax;
    const glm::uvec2 voxels(dims[sliceAcross(slice.axis)] * panes.x, dims[sliceUp(slice.axis)] * panes.y);
    const uint32_t longer = std::max(1u, std::max(voxels.x, voxels.y));
    const uint32_t scale = std::max(1u, (kSliceMinTexels + longer - 1) / longer);
    return voxels * scale;
}

} // namespace

glm::uvec2 layOutProbeTiles(gpu::VisualiseConstants& constants, const gi::ScreenProbeResources& resources,
                            uint32_t perProbe, uint32_t tileWidth) {
    constants.probeGrid = glm::uvec2(resources.gridWidth, resources.probeRows());
    constants.entriesPerProbe = perProbe;
    constants.tileWidth = tileWidth;
    return {resources.gridWidth * tileWidth,
            resources.probeRows() * ((perProbe + tileWidth - 1) / tileWidth)};
}

void appendSdfViews(std::vector<BufferView>& views) {
    views.push_back(giView("sdf: global SDF slice", Source::SdfSlice));
    for (sdf::SdfField field : {sdf::SdfField::Near, sdf::SdfField::Far, sdf::SdfField::Cone}) {
        BufferView view =
            giView(std::string("sdf: traced normals, ") + sdf::fieldName(field), Source::SdfTrace);
        view.field = field;
        views.push_back(std::move(view));
    }
}

void appendSurfaceCacheViews(std::vector<BufferView>& views, const gi::LumenGi& lumen) {
    const surface_cache::SurfaceCache& cache = lumen.surfaceCache();
    const auto& atlas = cache.atlas();
    for (uint32_t i = 0; i < surface_cache::kAtlasLayerCount; ++i) {
        const auto layer = static_cast<surface_cache::AtlasLayer>(i);
        const surface_cache::AtlasLayerView where = atlas.layer(layer);
        const uint32_t mode = layer == surface_cache::AtlasLayer::Albedo   ? LUMINA_VISUALISE_COLOR
                              : layer == surface_cache::AtlasLayer::Normal ? LUMINA_VISUALISE_NORMAL
                                                                           : LUMINA_VISUALISE_RADIANCE;
        BufferView view = textureView(std::string("surface cache: ") + surface_cache::atlasLayerName(layer),
                                      where.texture, mode);
        if (where.texture->desc().dimension == rhi::TextureDimension::Texture2DArray) {
            view.source = Source::TextureLayer;
            view.layer = where.arrayLayer;
        }
        views.push_back(std::move(view));
    }
    views.push_back(giView("surface cache: card outlines over the final image", Source::CardOutlinesScreen));
    // Two of the atlas's plain 2D layers: the captured surfaces, and the light they carry.
    for (const auto layer : {surface_cache::AtlasLayer::Albedo, surface_cache::AtlasLayer::FinalLighting}) {
        const bool albedo = layer == surface_cache::AtlasLayer::Albedo;
        BufferView view =
            giView(std::string("surface cache: card outlines over the atlas ") +
                       surface_cache::atlasLayerName(layer),
                   Source::CardOutlinesAtlas, albedo ? LUMINA_VISUALISE_COLOR : LUMINA_VISUALISE_RADIANCE);
        view.texture = atlas.layer(layer).texture;
        views.push_back(std::move(view));
    }
    const auto radiosity = [&](std::string name, rhi::BufferHandle probes, uint32_t mode) {
        BufferView view =
            giView("surface cache: radiosity probes, " + std::move(name), Source::RadiosityProbes, mode);
        view.buffer = std::move(probes);
        views.push_back(std::move(view));
    };
    radiosity("irradiance (filtered)", cache.radiosity().probes(), LUMINA_VISUALISE_RADIANCE);
    radiosity("irradiance (traced)", cache.radiosity().tracedProbes(), LUMINA_VISUALISE_RADIANCE);
    radiosity("normal", cache.radiosity().probes(), LUMINA_VISUALISE_NORMAL);
    views.push_back(
        giView("surface cache: voxel lighting slice", Source::VoxelSlice, LUMINA_VISUALISE_RADIANCE));
}

void appendScreenProbeViews(std::vector<BufferView>& views, const gi::LumenGi& lumen) {
    const gi::ScreenProbeResources& probes = lumen.screenProbes().resources();
    const auto probeView = [&](std::string name, rhi::BufferHandle buffer, Source source, uint32_t perProbe,
                               uint32_t mode, float hi = 1.0f) -> BufferView& {
        BufferView view = giView("screen probes: " + std::move(name), source, mode);
        view.buffer = std::move(buffer);
        view.perProbe = perProbe;
        view.tileWidth = kProbeTile;
        view.hi = hi;
        views.push_back(std::move(view));
        return views.back();
    };
    probeView("BRDF PDF", probes.brdfPdf, Source::ProbeTable, kProbeTexels, LUMINA_VISUALISE_SCALAR,
              kPdfDisplayMax);
    probeView("lighting PDF", probes.lightingPdf, Source::ProbeTable, kProbeTexels, LUMINA_VISUALISE_SCALAR,
              kPdfDisplayMax);
    probeView("ray directions", probes.rays, Source::ProbeRays, probes.raysPerProbe, LUMINA_VISUALISE_NORMAL);
    probeView("ray radiance", probes.rayRadiance, Source::ProbeMap, probes.raysPerProbe,
              LUMINA_VISUALISE_RADIANCE);
    probeView("frame radiance", probes.frameRadiance, Source::ProbeMap, kProbeTexels,
              LUMINA_VISUALISE_RADIANCE);
    probeView("history radiance", nullptr, Source::ProbeMap, kProbeTexels, LUMINA_VISUALISE_RADIANCE)
        .historyHalf = true;
    probeView("filtered radiance", probes.filtered, Source::ProbeMap, kProbeTexels,
              LUMINA_VISUALISE_RADIANCE);
    probeView("SH radiance (the low-pass)", probes.sh, Source::ProbeSh, kProbeTexels,
              LUMINA_VISUALISE_RADIANCE);
    views.push_back(
        textureView("screen probes: irradiance atlas", probes.irradiance, LUMINA_VISUALISE_RADIANCE));
    views.push_back(textureView("screen probes: gather (before the screen filter)", probes.gather,
                                LUMINA_VISUALISE_RADIANCE));
}

uint32_t sliceCascade(const sdf::SceneSdf& sdfs, const SliceSettings& slice) {
    const uint32_t count = sdfs.data().cascades.count;
    if (slice.cascade >= 0) {
        return std::min(uint32_t(slice.cascade), count - 1);
    }
    for (uint32_t c = 0; c + 1 < count; ++c) {
        const sdf::GlobalSdfSettings grid = sdfs.cascadeGrid(c);
        const float lo = grid.boundsMin[slice.axis];
        const float hi = lo + float(grid.dims[slice.axis]) * grid.voxelSize;
        if (slice.position >= lo + grid.voxelSize && slice.position <= hi - grid.voxelSize) {
            return c;
        }
    }
    return count - 1;
}

rhi::TextureHandle Visualiser::recordGiView(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                                            const BufferView& view, const ViewSettings& settings,
                                            gpu::VisualiseConstants constants) {
    const gi::LumenGi& lumen = *renderer.lumen();
    const surface_cache::SurfaceCache& cache = lumen.surfaceCache();
    const gi::ScreenProbeResources& probes = lumen.screenProbes().resources();
    switch (view.source) {
    case Source::SdfSlice:
        return recordSdfSlice(frame, lumen, settings, constants);
    case Source::SdfTrace:
        return recordSdfTrace(frame, renderer, view, settings, constants);
    case Source::VoxelSlice:
        return recordVoxelSlice(frame, lumen, settings, constants);
    default:
        break;
    }
    glm::uvec2 size(0);
    gi::ComputePass pass = [&] {
        switch (view.source) {
        case Source::CardOutlinesScreen: {
            const gi::DeferredRenderer& deferred = renderer.deferred();
            size = {deferred.ldr()->desc().width, deferred.ldr()->desc().height};
            return std::move(frame.compute("viewer: visualise", "viewer/visualise_cards.screen")
                                 .read(0, deferred.ldr())
                                 .read(1, deferred.gbuffer().position)
                                 .read(2, deferred.gbuffer().normal)
                                 .read(3, cache.cardBvhBuffer())
                                 .read(4, cache.cardBuffer()));
        }
        case Source::CardOutlinesAtlas:
            size = {view.texture->desc().width, view.texture->desc().height};
            return std::move(frame.compute("viewer: visualise", "viewer/visualise_cards.atlas")
                                 .read(0, view.texture)
                                 .read(4, cache.cardBuffer())
                                 .read(5, cache.tileOwner()));
        case Source::RadiosityProbes:
            size = glm::uvec2(cache.atlas().size() / LUMINA_RADIOSITY_PROBE_SPACING);
            return std::move(frame.compute("viewer: visualise", "viewer/visualise_lighting.radiosityProbes")
                                 .read(0, view.buffer));
        case Source::ProbeRays:
            size = layOutProbeTiles(constants, probes, view.perProbe, view.tileWidth);
            return std::move(
                frame.compute("viewer: visualise", "viewer/visualise_screen_probes.rayDirections")
                    .read(0, view.buffer));
        default: // Source::ProbeSh
            size = layOutProbeTiles(constants, probes, view.perProbe, view.tileWidth);
            return std::move(frame.compute("viewer: visualise", "viewer/visualise_screen_probes.shRadiance")
                                 .read(1, view.buffer)
                                 .read(2, probes.probes[lumen.screenProbes().current()]));
        }
    }();
    constants.size = glm::uvec2(size.x, size.y);
    pass.write(0, output(frame.device(), size.x, size.y))
        .constants(constants)
        .dispatchThreads(size.x, size.y, {LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE});
    return output_;
}

rhi::TextureHandle Visualiser::recordSdfSlice(gi::FrameContext& frame, const gi::LumenGi& lumen,
                                              const ViewSettings& settings,
                                              gpu::VisualiseConstants constants) {
    const sdf::SceneSdf& sdfs = lumen.sdf();
    const uint32_t cascade = sliceCascade(sdfs, settings.slice);
    const sdf::GlobalSdfSettings grid = sdfs.cascadeGrid(cascade);
    const glm::vec3 boxMax = grid.boundsMin + glm::vec3(grid.dims) * grid.voxelSize;
    const glm::uvec2 size = layOutSlice(constants, settings.slice, grid.boundsMin, boxMax, grid.dims, {1, 1});
    constants.sdfCascade = cascade;
    constants.size = glm::uvec2(size.x, size.y);
    sdfs.bindForTracing(frame.compute("viewer: visualise", "viewer/visualise_sdf"))
        .write(0, output(frame.device(), size.x, size.y))
        .constants(constants)
        .dispatchThreads(size.x, size.y, {LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE});
    return output_;
}

rhi::TextureHandle Visualiser::recordSdfTrace(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                                              const BufferView& view, const ViewSettings& settings,
                                              gpu::VisualiseConstants constants) {
    const rhi::TextureDesc& image = renderer.deferred().ldr()->desc();
    if (!tracer_ || tracer_->width() != image.width || tracer_->height() != image.height) {
        tracer_ = std::make_unique<sdf::SdfCameraTracer>(frame.device(), image.width, image.height);
    }
    tracer_->record(frame, renderer.lumen()->sdf(), settings.camera, view.field,
                    sdf::defaultTraceParams(view.field, settings.camera.farPlane), "viewer: sdf trace",
                    std::tan(kConeHalfAngle));
    // The traced pixels are a buffer of float4 (0.5 n + 0.5, t): a probe map of one-texel tiles.
    constants.size = glm::uvec2(image.width, image.height);
    constants.probeGrid = glm::uvec2(image.width, image.height);
    constants.entriesPerProbe = 1;
    constants.tileWidth = 1;
    frame.compute("viewer: visualise", "viewer/visualise.probeMap")
        .read(3, tracer_->pixels())
        .write(0, output(frame.device(), image.width, image.height))
        .constants(constants)
        .dispatchThreads(image.width, image.height,
                         {LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE});
    return output_;
}

rhi::TextureHandle Visualiser::recordVoxelSlice(gi::FrameContext& frame, const gi::LumenGi& lumen,
                                                const ViewSettings& settings,
                                                gpu::VisualiseConstants constants) {
    const surface_cache::VoxelLightingPass& voxels = lumen.surfaceCache().voxelLighting();
    const gpu::VoxelGridInfo& grid = voxels.grid();
    const glm::vec3 boxMin = grid.boxMin;
    const glm::uvec3 dims = grid.dims;
    const glm::vec3 boxMax = boxMin + glm::vec3(dims) * grid.voxelSize;
    const glm::uvec2 size =
        layOutSlice(constants, settings.slice, boxMin, boxMax, dims, {kVoxelPanesAcross, kVoxelPanesDown});
    constants.sliceDims = dims.x; // cubic (voxelGridOver)
    constants.size = glm::uvec2(size.x, size.y);
    frame.compute("viewer: visualise", "viewer/visualise_lighting.voxelSlice")
        .read(1, voxels.volume())
        .write(0, output(frame.device(), size.x, size.y))
        .constants(constants)
        .dispatchThreads(size.x, size.y, {LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE});
    return output_;
}

} // namespace lumina::app::viewer
