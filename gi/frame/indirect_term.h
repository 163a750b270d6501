#pragma once
// The radiance a FrameRenderer's indirect term adds at the primary hit, as its composite
// computes it (docs/gi.md): indirectScale x irradiance x albedo. What `lumina bench` measures
// as the indirect error and `--dump-buffers` writes as indirect.exr.
#include "gi/frame/frame_renderer.h"
#include "gi/image/image.h"

namespace lumina::gi {

// scale x irradiance x albedo per channel (R, G, B of both; ImageError when the sizes differ).
image::Image indirectRadiance(const image::Image& irradiance, const image::Image& albedo, float scale);

// The renderer's indirect term read back (waits for the GPU); black without GI.
image::Image readIndirectRadiance(rhi::IDevice& device, const FrameRenderer& renderer);

} // namespace lumina::gi
