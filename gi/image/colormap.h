#pragma once
// False-colour maps for error images.
#include <array>
#include <cstdint>

namespace lumina::image {

using Rgb8 = std::array<uint8_t, 3>;

// Perceptually uniform dark-to-bright map: matplotlib's "magma" (van der Walt and Smith,
// CC0) sampled at 9 evenly spaced stops and interpolated linearly in sRGB between them.
// t is clamped to [0,1]; NaN gives kHeatmapInvalid.
Rgb8 magma(float t);

// Colour for pixels whose value is not finite: pure green, absent from magma.
inline constexpr Rgb8 kHeatmapInvalid = {0, 255, 0};

} // namespace lumina::image
