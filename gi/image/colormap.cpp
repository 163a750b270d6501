#include "gi/image/colormap.h"

#include <cmath>

namespace lumina::image {

namespace {

// matplotlib 3.6 magma(t) at t = 0, 1/8, ..., 1 (display-encoded sRGB).
constexpr float kMagmaStops[9][3] = {
    {0.0015f, 0.0005f, 0.0139f}, {0.1131f, 0.0655f, 0.2768f}, {0.3167f, 0.0717f, 0.4854f},
    {0.5128f, 0.1482f, 0.5076f}, {0.7164f, 0.2150f, 0.4753f}, {0.9043f, 0.3196f, 0.3881f},
    {0.9867f, 0.5356f, 0.3822f}, {0.9969f, 0.7696f, 0.5349f}, {0.9871f, 0.9914f, 0.7495f},
};
constexpr int kMagmaSegments = 8;

} // namespace

Rgb8 magma(float t) {
    if (std::isnan(t)) {
        return kHeatmapInvalid;
    }
    const float u = (t > 0.0f ? (t < 1.0f ? t : 1.0f) : 0.0f) * kMagmaSegments;
    const int i = u >= kMagmaSegments ? kMagmaSegments - 1 : int(u);
    const float f = u - float(i);
    Rgb8 out{};
    for (int c = 0; c < 3; ++c) {
        const float v = kMagmaStops[i][c] + f * (kMagmaStops[i + 1][c] - kMagmaStops[i][c]);
        out[size_t(c)] = uint8_t(std::lround(v * 255.0f));
    }
    return out;
}

} // namespace lumina::image
