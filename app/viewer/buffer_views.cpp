#include "app/viewer/buffer_views.h"

#include "gi/surface_cache/surface_cache_atlas.h"

namespace lumina::app::viewer {

namespace {

using Source = BufferView::Source;

// Screen-probe maps hold 8 x 8 octahedral texels per probe (LUMINA_SP_OCT_SIZE); rays are tiled
// 8 wide likewise.
constexpr uint32_t kProbeTile = 8;
constexpr uint32_t kProbeTexels = kProbeTile * kProbeTile;
// PDF tables: uniform is 1/64 per texel; 4x uniform shows as white.
constexpr float kPdfDisplayMax = 4.0f / float(kProbeTexels);

BufferView texture(std::string name, rhi::TextureHandle texture, uint32_t mode, float lo = 0.0f,
                   float hi = 1.0f) {
    BufferView view;
    view.name = std::move(name);
    view.source = Source::Texture;
    view.texture = std::move(texture);
    view.mode = mode;
    view.lo = lo;
    view.hi = hi;
    return view;
}

} // namespace

std::vector<BufferView> listBufferViews(const gi::FrameRenderer& renderer, float sceneDiagonal) {
    std::vector<BufferView> views;
    BufferView final;
    final.name = "final image";
    views.push_back(std::move(final));
    const gi::DeferredRenderer& deferred = renderer.deferred();
    const gi::GBuffer& gbuffer = deferred.gbuffer();
    views.push_back(texture("gbuffer: albedo", gbuffer.albedo, LUMINA_VISUALISE_COLOR));
    views.push_back(texture("gbuffer: normal", gbuffer.normal, LUMINA_VISUALISE_NORMAL));
    views.push_back(texture("gbuffer: emission", gbuffer.material, LUMINA_VISUALISE_RADIANCE));
    views.push_back(
        texture("gbuffer: view depth", gbuffer.position, LUMINA_VISUALISE_ALPHA, 0.0f, sceneDiagonal));
    views.push_back(texture("gbuffer: depth buffer", gbuffer.depth, LUMINA_VISUALISE_SCALAR));
    if (auto sun = deferred.sunShadowMap()) {
        views.push_back(texture("shadows: sun shadow map", sun, LUMINA_VISUALISE_SCALAR));
    }
    if (auto cubes = deferred.pointShadowMaps()) {
        static constexpr const char* kFaces[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
        for (uint32_t face = 0; face < 6; ++face) {
            BufferView view = texture(std::string("shadows: first point light, face ") + kFaces[face], cubes,
                                      LUMINA_VISUALISE_SCALAR, 0.0f, sceneDiagonal);
            view.source = Source::TextureLayer;
            view.layer = face;
            view.viewAsArray = true;
            views.push_back(std::move(view));
        }
    }
    views.push_back(texture("deferred: direct light", deferred.direct(), LUMINA_VISUALISE_RADIANCE));
    views.push_back(texture("deferred: composite (HDR)", deferred.hdr(), LUMINA_VISUALISE_RADIANCE));

    const gi::LumenGi* lumen = renderer.lumen();
    if (lumen == nullptr) {
        return views;
    }
    views.push_back(texture("indirect: irradiance E", renderer.indirect(), LUMINA_VISUALISE_RADIANCE));
    const auto& atlas = lumen->surfaceCache().atlas();
    for (uint32_t i = 0; i < surface_cache::kAtlasLayerCount; ++i) {
        const auto layer = static_cast<surface_cache::AtlasLayer>(i);
        const surface_cache::AtlasLayerView where = atlas.layer(layer);
        const uint32_t mode = layer == surface_cache::AtlasLayer::Albedo   ? LUMINA_VISUALISE_COLOR
                              : layer == surface_cache::AtlasLayer::Normal ? LUMINA_VISUALISE_NORMAL
                                                                           : LUMINA_VISUALISE_RADIANCE;
        BufferView view = texture(std::string("surface cache: ") + surface_cache::atlasLayerName(layer),
                                  where.texture, mode);
        if (where.texture->desc().dimension == rhi::TextureDimension::Texture2DArray) {
            view.source = Source::TextureLayer;
            view.layer = where.arrayLayer;
        }
        views.push_back(std::move(view));
    }

    const gi::ScreenProbeResources& probes = lumen->screenProbes().resources();
    const uint32_t current = lumen->screenProbes().current();
    const auto probeBuffer = [&](std::string name, rhi::BufferHandle buffer, Source source, uint32_t perProbe,
                                 uint32_t mode, float hi = 1.0f) {
        BufferView view;
        view.name = "screen probes: " + std::move(name);
        view.source = source;
        view.buffer = std::move(buffer);
        view.perProbe = perProbe;
        view.tileWidth = kProbeTile;
        view.mode = mode;
        view.hi = hi;
        views.push_back(std::move(view));
    };
    probeBuffer("BRDF PDF", probes.brdfPdf, Source::ProbeTable, kProbeTexels, LUMINA_VISUALISE_SCALAR,
                kPdfDisplayMax);
    probeBuffer("lighting PDF", probes.lightingPdf, Source::ProbeTable, kProbeTexels, LUMINA_VISUALISE_SCALAR,
                kPdfDisplayMax);
    probeBuffer("ray radiance", probes.rayRadiance, Source::ProbeMap, probes.raysPerProbe,
                LUMINA_VISUALISE_RADIANCE);
    probeBuffer("frame radiance", probes.frameRadiance, Source::ProbeMap, kProbeTexels,
                LUMINA_VISUALISE_RADIANCE);
    probeBuffer("history radiance", probes.history[current], Source::ProbeMap, kProbeTexels,
                LUMINA_VISUALISE_RADIANCE);
    probeBuffer("filtered radiance", probes.filtered, Source::ProbeMap, kProbeTexels,
                LUMINA_VISUALISE_RADIANCE);
    views.push_back(texture("screen probes: irradiance atlas", probes.irradiance, LUMINA_VISUALISE_RADIANCE));
    views.push_back(texture("screen probes: gather (before the screen filter)", probes.gather,
                            LUMINA_VISUALISE_RADIANCE));
    return views;
}

rhi::TextureHandle Visualiser::record(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                                      const BufferView& view, float exposureScale) {
    if (view.source == Source::Final) {
        return renderer.deferred().ldr();
    }
    const bool probes = view.source == Source::ProbeMap || view.source == Source::ProbeTable;
    const gi::ScreenProbeResources* resources =
        probes ? &renderer.lumen()->screenProbes().resources() : nullptr;
    uint32_t width = 0, height = 0;
    if (probes) {
        width = resources->gridWidth * view.tileWidth;
        height = resources->gridHeight * ((view.perProbe + view.tileWidth - 1) / view.tileWidth);
    } else {
        width = view.texture->desc().width;
        height = view.texture->desc().height;
    }
    if (!output_ || output_->desc().width != width || output_->desc().height != height) {
        output_ =
            frame.device().createTexture({.format = rhi::Format::RGBA8_UNORM,
                                          .width = width,
                                          .height = height,
                                          .usage = rhi::TextureUsage::Storage | rhi::TextureUsage::Sampled,
                                          .debugName = "viewer: debug view"});
    }
    gpu::VisualiseConstants constants{};
    constants.sizeModeLayer = {width, height, view.mode, view.layer};
    constants.rangeExposure = {view.lo, view.hi, exposureScale, 0.0f};
    if (probes) {
        constants.probeGrid = {resources->gridWidth, resources->gridHeight, view.perProbe, view.tileWidth};
    }

    // The entry point for each kind of source, and the t register it reads (visualise.hlsl).
    struct Entry {
        const char* kernel;
        uint32_t reg;
    };
    static constexpr Entry kEntries[] = {
        {"viewer/visualise", 0},             // Final (not visualised)
        {"viewer/visualise", 0},             // Texture
        {"viewer/visualise.arrayLayer", 1},  // TextureLayer
        {"viewer/visualise.uintTexture", 2}, // UintTexture
        {"viewer/visualise.probeMap", 3},    // ProbeMap
        {"viewer/visualise.probeTable", 4},  // ProbeTable
    };
    const auto [kernel, reg] = kEntries[size_t(view.source)];
    gi::ComputePass pass = frame.compute("viewer: visualise", kernel);
    if (probes) {
        pass.read(reg, view.buffer);
    } else {
        rhi::BindingSetItem item = rhi::BindingSetItem::sampledTexture(reg, view.texture);
        if (view.viewAsArray) {
            item.overrideDimension = true;
            item.viewDimension = rhi::TextureDimension::Texture2DArray;
        }
        pass.bind(std::move(item));
    }
    pass.write(0, output_)
        .constants(constants)
        .dispatchThreads(width, height, {LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE});
    return output_;
}

} // namespace lumina::app::viewer
