#pragma once
// Every intermediate of the screen-probe gather as images, for tests and `--dump-buffers`:
// per-probe data laid out over the probe grid (probe (x, y) at tile (x, y)), so that a picture
// of a buffer shows the screen it came from.
#include "gi/image/image.h"
#include "gi/screen_probes/screen_probe_gather.h"
#include "rhi/rhi.h"

#include <filesystem>
#include <span>
#include <vector>

namespace lumina::gi {

// Per-texel float4 data (radiance maps: frame, history, filtered), one 8 x 8 tile per probe: R, G,
// B, A.
image::Image probeMapImage(std::span<const gpu::float4> texels, uint32_t gridWidth, uint32_t gridHeight);
// Per-texel scalars (PDF tables), one 8 x 8 tile per probe, in R, G and B.
image::Image probeTableImage(std::span<const float> texels, uint32_t gridWidth, uint32_t gridHeight);
// Per-ray float4 data, one 8 x ceil(rays / 8) tile per probe: R, G, B, A.
image::Image probeRayImage(std::span<const gpu::float4> rays, uint32_t raysPerProbe, uint32_t gridWidth,
                           uint32_t gridHeight);

// Writes every intermediate of the last frame recorded into `directory` (created if needed) as
// EXR: probes (position + view depth, normal + valid), both PDFs, ray directions + weights, hits
// (t, miss, steps, occlusion), the near field's radiance and source (when it ran), ray radiance,
// the composite, history, filtered radiance, SH, the irradiance atlas, the gather and the screen
// result. Returns the paths written.
std::vector<std::filesystem::path> dumpScreenProbeBuffers(rhi::IDevice& device,
                                                          const ScreenProbeGather& gather,
                                                          const std::filesystem::path& directory);

} // namespace lumina::gi
