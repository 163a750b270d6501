#pragma once
// GPU targets back to CPU images, for `lumina render --dump-buffers`, goldens and tests.
#include "gi/image/display.h"
#include "gi/image/image.h"
#include "rhi/rhi.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lumina::gi {

class DeferredRenderer;

// One layer of a texture as float channels: R, G, B, A for RGBA formats; single-channel
// formats (R32F, D32) fill R, G and B with the value so every EXR reader can show them.
// Throws rhi::Error for formats it does not convert.
image::Image readTextureImage(rhi::IDevice& device, rhi::ITexture& texture, uint32_t arrayLayer = 0);

// The six faces of one cube of a cube array, side by side (+X, -X, +Y, -Y, +Z, -Z).
image::Image readCubeStrip(rhi::IDevice& device, rhi::ITexture& cubes, uint32_t cube);

// Writes every intermediate of the last frame into `directory` (created if needed): the
// GBuffer targets, the shadow maps, direct light, HDR (EXR) and LDR (PNG), plus a PNG view of
// each; returns the paths written. `display` is the transform of the radiance PNGs.
std::vector<std::filesystem::path> dumpDeferredBuffers(rhi::IDevice& device, const DeferredRenderer& renderer,
                                                       const std::filesystem::path& directory,
                                                       const image::DisplayOptions& display);

// The RGBA8 display image (already sRGB-encoded) as an R, G, B image for writeDisplayPng.
image::Image displayImage(const image::Image& rgba8);

} // namespace lumina::gi
