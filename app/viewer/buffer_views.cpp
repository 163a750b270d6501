#include "app/viewer/buffer_views.h"

namespace lumina::app::viewer {

using Source = BufferView::Source;

BufferView textureView(std::string name, rhi::TextureHandle texture, uint32_t mode, float lo, float hi) {
    BufferView view;
    view.name = std::move(name);
    view.source = Source::Texture;
    view.texture = std::move(texture);
    view.mode = mode;
    view.lo = lo;
    view.hi = hi;
    return view;
}

std::vector<BufferView> listBufferViews(const gi::FrameRenderer& renderer, float sceneDiagonal) {
    std::vector<BufferView> views;
    BufferView final;
    final.name = "final image";
    views.push_back(std::move(final));
    const gi::DeferredRenderer& deferred = renderer.deferred();
    const gi::GBuffer& gbuffer = deferred.gbuffer();
    views.push_back(textureView("gbuffer: albedo", gbuffer.albedo, LUMINA_VISUALISE_COLOR));
    views.push_back(textureView("gbuffer: normal", gbuffer.normal, LUMINA_VISUALISE_NORMAL));
    views.push_back(textureView("gbuffer: emission", gbuffer.material, LUMINA_VISUALISE_RADIANCE));
    views.push_back(
        textureView("gbuffer: view depth", gbuffer.position, LUMINA_VISUALISE_ALPHA, 0.0f, sceneDiagonal));
    views.push_back(textureView("gbuffer: depth buffer", gbuffer.depth, LUMINA_VISUALISE_SCALAR));
    if (auto sun = deferred.sunShadowMap()) {
        views.push_back(textureView("shadows: sun shadow map", sun, LUMINA_VISUALISE_SCALAR));
    }
    if (auto cubes = deferred.pointShadowMaps()) {
        static constexpr const char* kFaces[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
        for (uint32_t face = 0; face < 6; ++face) {
            BufferView view = textureView(std::string("shadows: first point light, face ") + kFaces[face],
                                          cubes, LUMINA_VISUALISE_SCALAR, 0.0f, sceneDiagonal);
            view.source = Source::TextureLayer;
            view.layer = face;
            view.viewAsArray = true;
            views.push_back(std::move(view));
        }
    }
    views.push_back(textureView("deferred: direct light", deferred.direct(), LUMINA_VISUALISE_RADIANCE));
    views.push_back(textureView("deferred: composite (HDR)", deferred.hdr(), LUMINA_VISUALISE_RADIANCE));

    if (renderer.gi() == nullptr) {
        return views;
    }
    views.push_back(textureView("indirect: irradiance E", renderer.indirect(), LUMINA_VISUALISE_RADIANCE));
    // What the technique exposes itself (GiTechniqueRenderer::debugTextures).
    for (const gi::GiDebugTexture& debug : renderer.gi()->debugTextures()) {
        views.push_back(textureView(debug.name, debug.texture, LUMINA_VISUALISE_RADIANCE));
    }
    const gi::LumenGi* lumen = renderer.lumen();
    if (lumen == nullptr) {
        return views;
    }
    appendSdfViews(views);
    appendSurfaceCacheViews(views, *lumen);
    appendScreenProbeViews(views, *lumen);
    return views;
}

Visualiser::Visualiser() = default;
Visualiser::~Visualiser() = default;

const rhi::TextureHandle& Visualiser::output(rhi::IDevice& device, uint32_t width, uint32_t height) {
    if (!output_ || output_->desc().width != width || output_->desc().height != height) {
        output_ = device.createTexture({.format = rhi::Format::RGBA8_UNORM,
                                        .width = width,
                                        .height = height,
                                        .usage = rhi::TextureUsage::Storage | rhi::TextureUsage::Sampled,
                                        .debugName = "viewer: debug view"});
    }
    return output_;
}

rhi::TextureHandle Visualiser::record(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                                      const BufferView& view, const ViewSettings& settings) {
    if (view.source == Source::Final) {
        return renderer.deferred().ldr();
    }
    gpu::VisualiseConstants constants{};
    constants.mode = view.mode;
    constants.layer = view.layer;
    constants.rangeLo = view.lo;
    constants.rangeHi = view.hi;
    constants.exposureScale = settings.exposureScale;
    if (view.source >= Source::SdfSlice) {
        return recordGiView(frame, renderer, view, settings, constants);
    }
    return recordBufferView(frame, renderer, view, constants);
}

rhi::TextureHandle Visualiser::recordBufferView(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                                                const BufferView& view, gpu::VisualiseConstants constants) {
    const bool probes = view.source == Source::ProbeMap || view.source == Source::ProbeTable;
    const gi::ScreenProbeResources* resources =
        probes ? &renderer.lumen()->screenProbes().resources() : nullptr;
    uint32_t width = 0, height = 0;
    if (probes) {
        const glm::uvec2 size = layOutProbeTiles(constants, *resources, view.perProbe, view.tileWidth);
        width = size.x;
        height = size.y;
    } else {
        width = view.texture->desc().width;
        height = view.texture->desc().height;
    }
    constants.size = glm::uvec2(width, height);

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
        // The history is a ping-pong pair: this frame's half, not the one current when listed.
        pass.read(reg, view.historyHalf ? resources->history[renderer.lumen()->screenProbes().current()]
                                        : view.buffer);
    } else {
        rhi::BindingSetItem item = rhi::BindingSetItem::sampledTexture(reg, view.texture);
        if (view.viewAsArray) {
            item.overrideDimension = true;
            item.viewDimension = rhi::TextureDimension::Texture2DArray;
        }
        pass.bind(std::move(item));
    }
    pass.write(0, output(frame.device(), width, height))
        .constants(constants)
        .dispatchThreads(width, height, {LUMINA_VISUALISE_GROUP_SIZE, LUMINA_VISUALISE_GROUP_SIZE});
    return output_;
}

} // namespace lumina::app::viewer
