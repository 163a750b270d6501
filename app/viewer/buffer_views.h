#pragma once
// The debug views: every intermediate buffer a FrameRenderer exposes (GBuffer targets, depth,
// shadow maps, direct light, HDR, and for lumen the indirect term, the SDFs, each surface-cache
// layer, card outlines, radiosity probes, the voxel lighting and the screen probes' buffers), and
// the visualise kernels (shaders/viewer/visualise*.hlsl) that turn the chosen one into a display
// image each frame, which the viewer shows full window.
#include "gi/core/frame_context.h"
#include "gi/frame/frame_renderer.h"
#include "gi/scene/scene.h"
#include "gi/sdf/sdf_views.h"
#include "shaders/viewer/viewer_shared.h"

#include <memory>
#include <string>
#include <vector>

namespace lumina::app::viewer {

struct BufferView {
    enum class Source : uint8_t {
        Final,
        Texture,
        TextureLayer,
        UintTexture,
        ProbeMap,
        ProbeTable,
        // The lumen technique's GI views (gi_views.cpp), each reading what its subsystem holds:
        SdfSlice,           // a cascade of the global SDF, cut at ViewSettings::slice
        SdfTrace,           // camera rays traced through the SDFs by the viewer (field)
        CardOutlinesScreen, // the final image, each surface tinted and outlined by its card
        CardOutlinesAtlas,  // an atlas layer (texture), each card's rectangle outlined
        RadiosityProbes,    // a buffer of RadiosityProbe over the atlas's probe grid
        VoxelSlice,         // the voxel lighting volume, cut at ViewSettings::slice
        ProbeRays,          // the screen probes' ray list
        ProbeSh,            // the screen probes' SH, evaluated over each probe's map
    };
    std::string name;
    Source source = Source::Final;
    rhi::TextureHandle texture;
    uint32_t layer = 0;
    bool viewAsArray = false; // a cube array read as a 2D array
    rhi::BufferHandle buffer;
    uint32_t perProbe = 0, tileWidth = 0; // probe buffers
    uint32_t mode = LUMINA_VISUALISE_COLOR;
    float lo = 0.0f, hi = 1.0f;                // scalar range
    sdf::SdfField field = sdf::SdfField::Near; // SdfTrace
    bool historyHalf = false; // ProbeMap: buffer is the probe history; this frame's half is read

    bool isSlice() const { return source == Source::SdfSlice || source == Source::VoxelSlice; }
};

// Where the slice views cut their volume.
struct SliceSettings {
    uint32_t axis = LUMINA_VISUALISE_AXIS_Z;
    float position = 0.0f; // world, along the axis
    int cascade = -1;      // SDF slice: the cascade shown; -1: the finest whose window holds the plane
};

// What a view needs besides the renderer's buffers.
struct ViewSettings {
    float exposureScale = 1.0f;
    SliceSettings slice;
    scene::Camera camera; // the view the SDF trace shoots rays from (the renderer's)
};

// A view of a 2D texture.
BufferView textureView(std::string name, rhi::TextureHandle texture, uint32_t mode, float lo = 0.0f,
                       float hi = 1.0f);

// The final image first, then every buffer the renderer has this frame. Rebuilt whenever the
// renderer changes (technique, preset): the handles belong to it.
std::vector<BufferView> listBufferViews(const gi::FrameRenderer& renderer, float sceneDiagonal);
// The lumen views (gi_views.cpp), appended in the order of the view menu.
void appendSdfViews(std::vector<BufferView>& views);
void appendSurfaceCacheViews(std::vector<BufferView>& views, const gi::LumenGi& lumen);
void appendScreenProbeViews(std::vector<BufferView>& views, const gi::LumenGi& lumen);

// Probe views tile each probe's entries tileWidth wide (visualise_common.hlsli, probeEntry): sets
// the constants' probe grid and returns the image size.
glm::uvec2 layOutProbeTiles(gpu::VisualiseConstants& constants, const gi::ScreenProbeResources& resources,
                            uint32_t perProbe, uint32_t tileWidth);

// The SDF cascade a slice view shows (SliceSettings::cascade, or the finest that holds the plane).
uint32_t sliceCascade(const sdf::SceneSdf& sdfs, const SliceSettings& slice);

class Visualiser {
public:
    Visualiser();
    ~Visualiser();

    // Records the visualise kernel for `view` into a display texture sized like the buffer's
    // image and returns it; the final view returns the composite's LDR image as it is.
    rhi::TextureHandle record(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                              const BufferView& view, const ViewSettings& settings);

private:
    // The display texture, (re)made at this size.
    const rhi::TextureHandle& output(rhi::IDevice& device, uint32_t width, uint32_t height);
    rhi::TextureHandle recordBufferView(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                                        const BufferView& view, gpu::VisualiseConstants constants);
    // gi_views.cpp
    rhi::TextureHandle recordGiView(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                                    const BufferView& view, const ViewSettings& settings,
                                    gpu::VisualiseConstants constants);
    rhi::TextureHandle recordSdfSlice(gi::FrameContext& frame, const gi::LumenGi& lumen,
                                      const ViewSettings& settings, gpu::VisualiseConstants constants);
    rhi::TextureHandle recordSdfTrace(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                                      const BufferView& view, const ViewSettings& settings,
                                      gpu::VisualiseConstants constants);
    rhi::TextureHandle recordVoxelSlice(gi::FrameContext& frame, const gi::LumenGi& lumen,
                                        const ViewSettings& settings, gpu::VisualiseConstants constants);

    rhi::TextureHandle output_;
    std::unique_ptr<sdf::SdfCameraTracer> tracer_; // made on the first SDF trace view
};

} // namespace lumina::app::viewer
