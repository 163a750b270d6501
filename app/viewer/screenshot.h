#pragma once
// Screenshots of the viewer's frame: the composite at the render size, as `lumina render`
// writes it (PNG: the display image; EXR: the linear HDR radiance), so the two compare.
#include "gi/frame/frame_renderer.h"

#include <filesystem>

namespace lumina::app::viewer {

// Waits for the GPU. The extension picks the format (.png or .exr); throws otherwise.
void writeScreenshot(rhi::IDevice& device, const gi::FrameRenderer& renderer,
                     const std::filesystem::path& path);
// The window as shown, UI included: the back buffer (RGBA8, display-encoded) as PNG.
void writeWindowScreenshot(rhi::IDevice& device, rhi::ITexture& backbuffer,
                           const std::filesystem::path& path);

} // namespace lumina::app::viewer
