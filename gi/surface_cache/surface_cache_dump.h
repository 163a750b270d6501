#pragma once
// The surface cache as images, for `lumina render --dump-buffers` (docs/surface_cache.md):
//
//   surface_cache_<layer>.exr / .png  every atlas layer (albedo, normal, material, direct light,
//                                     indirect light, final lighting); the PNG views radiance
//                                     through the display transform, normals as n / 2 + 1/2
//   surface_cache_cards.png           the final layer with every card's rectangle outlined
//   surface_cache_card_ids.exr / .png each texel's owning card index (-1: none), and a colour
//                                     per card
//   surface_cache_radiosity_probes.exr / .png  one pixel per radiosity probe (every 4 x 4 texels):
//                                     the irradiance its L1 SH gives at its normal, A = valid
//   surface_cache_voxel_lighting.exr  the voxel lighting volume's z slices side by side, a row
//                                     of them per face direction
#include "gi/image/display.h"
#include "gi/surface_cache/surface_cache.h"

#include <filesystem>
#include <vector>

namespace lumina::surface_cache {

// Reads everything back (waits for the GPU) and writes it into `directory`; returns the paths.
std::vector<std::filesystem::path> dumpSurfaceCache(rhi::IDevice& device, const SurfaceCache& cache,
                                                    const std::filesystem::path& directory,
                                                    const image::DisplayOptions& display);

} // namespace lumina::surface_cache
