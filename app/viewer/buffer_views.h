#pragma once
// The debug views: every intermediate buffer a FrameRenderer exposes (GBuffer targets, depth,
// shadow maps, direct light, HDR, and for lumen the indirect term, each surface-cache layer and
// the screen probes' buffers), and the visualise kernel (shaders/viewer/visualise.hlsl) that
// turns the chosen one into a display image each frame, which the viewer shows full window.
#include "gi/core/frame_context.h"
#include "gi/frame/frame_renderer.h"
#include "shaders/viewer/viewer_shared.h"

#include <string>
#include <vector>

namespace lumina::app::viewer {

struct BufferView {
    enum class Source : uint8_t { Final, Texture, TextureLayer, UintTexture, ProbeMap, ProbeTable };
    std::string name;
    Source source = Source::Final;
    rhi::TextureHandle texture;
    uint32_t layer = 0;
    bool viewAsArray = false; // a cube array read as a 2D array
    rhi::BufferHandle buffer;
    uint32_t perProbe = 0, tileWidth = 0; // probe buffers
    uint32_t mode = LUMINA_VISUALISE_COLOR;
    float lo = 0.0f, hi = 1.0f; // scalar range
};

// The final image first, then every buffer the renderer has this frame. Rebuilt whenever the
// renderer changes (technique, preset): the handles belong to it.
std::vector<BufferView> listBufferViews(const gi::FrameRenderer& renderer, float sceneDiagonal);

class Visualiser {
public:
    // Records the visualise kernel for `view` into a display texture sized like the buffer's
    // image and returns it; the final view returns the composite's LDR image as it is.
    rhi::TextureHandle record(gi::FrameContext& frame, const gi::FrameRenderer& renderer,
                              const BufferView& view, float exposureScale);

private:
    rhi::TextureHandle output_;
};

} // namespace lumina::app::viewer
