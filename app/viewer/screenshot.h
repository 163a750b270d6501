#pragma once
// Screenshots of the viewer's frame at the render size: PNG the image on screen without the UI
// (the composite's display image, as `lumina render` writes it, or the debug view shown), EXR
// the composite's linear HDR radiance, so the two compare with `lumina render`'s.
#include "gi/frame/frame_renderer.h"

#include <filesystem>

namespace lumina::app::viewer {

// Waits for the GPU. The extension picks the format (.png or .exr); throws otherwise. `shown`:
// the display image on screen (RGBA8), the composite's or a debug view's.
void writeScreenshot(rhi::IDevice& device, const gi::FrameRenderer& renderer, rhi::ITexture& shown,
                     const std::filesystem::path& path);
// The window as shown, UI included: the back buffer (RGBA8, display-encoded) as PNG.
void writeWindowScreenshot(rhi::IDevice& device, rhi::ITexture& backbuffer,
                           const std::filesystem::path& path);

} // namespace lumina::app::viewer
