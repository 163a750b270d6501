#include "gi/image/display.h"

#include "shaders/common/tonemap_shared.h"

#include <cmath>

namespace lumina::image {

float toDisplay(float radiance, const DisplayOptions& options) {
    if (options.tonemap == Tonemap::Clamp) {
        return gpu::srgbOetf(radiance * std::exp2(options.exposureEv));
    }
    return gpu::tonemapToDisplay(radiance, std::exp2(options.exposureEv));
}

Image toDisplay(const Image& linear, const DisplayOptions& options) {
    if (!linear.hasRgb()) {
        throw ImageError("toDisplay: the image has no R, G, B channels");
    }
    const float scale = std::exp2(options.exposureEv);
    Image display = Image::rgb(linear.width(), linear.height());
    for (const char* name : {"R", "G", "B"}) {
        std::span<const float> in = linear.channel(name);
        std::span<float> out = display.channel(name);
        for (size_t i = 0; i < in.size(); ++i) {
            out[i] = options.tonemap == Tonemap::Clamp ? gpu::srgbOetf(in[i] * scale)
                                                       : gpu::tonemapToDisplay(in[i], scale);
        }
    }
    return display;
}

float srgbEncode(float linear) {
    return gpu::srgbOetf(linear);
}

float srgbDecode(float encoded) {
    return gpu::srgbEotf(encoded);
}

} // namespace lumina::image
