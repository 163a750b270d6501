#pragma once
// Every intermediate of a FrameRenderer's last frame as images (`lumina render --dump-buffers`):
// the deferred renderer's targets (gi/deferred/buffer_readback.h) and, for lumen, the indirect
// term, the surface cache (gi/surface_cache/surface_cache_dump.h) and the screen probes
// (gi/screen_probes/screen_probe_readback.h).
#include "gi/frame/frame_renderer.h"
#include "gi/image/display.h"

#include <filesystem>
#include <vector>

namespace lumina::gi {

// Waits for the GPU; returns the paths written.
std::vector<std::filesystem::path> dumpFrameBuffers(rhi::IDevice& device, const FrameRenderer& renderer,
                                                    const std::filesystem::path& directory,
                                                    const image::DisplayOptions& display);

} // namespace lumina::gi
