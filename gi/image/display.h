#pragma once
// Linear HDR radiance to display-encoded sRGB, the one display transform of the project:
//   display = srgbOetf(acesFitted(2^exposureEv * radiance))   per R, G, B channel,
// with the curve and the OETF from shaders/common/tonemap_shared.h, which the GPU composite
// includes too. See docs/measurement.md for the curve's source.
#include "gi/image/image.h"

namespace lumina::image {

enum class Tonemap {
    AcesFitted, // Narkowicz's ACES fit, then the sRGB OETF
    Clamp,      // no curve: clamp to [0,1], then the sRGB OETF (for images already in [0,1])
};

struct DisplayOptions {
    float exposureEv = 0.0f; // radiance is scaled by 2^exposureEv before the curve
    Tonemap tonemap = Tonemap::AcesFitted;
};

// One channel value through the display transform.
float toDisplay(float radiance, const DisplayOptions& options = {});

// R, G, B of a linear image through the display transform: an "R","G","B" image whose
// values are sRGB-encoded in [0,1] (NaN and -Inf become 0, +Inf 1). ImageError without R, G, B.
Image toDisplay(const Image& linear, const DisplayOptions& options = {});

// sRGB transfer functions on [0,1] (IEC 61966-2-1), from the shared header.
float srgbEncode(float linear);
float srgbDecode(float encoded);

} // namespace lumina::image
