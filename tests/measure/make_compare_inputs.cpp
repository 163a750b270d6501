// Writes the EXR inputs of the compare smoke test (compare_smoke.cmake) into the folder argv[1]:
//   ref.exr   64x48 smooth HDR gradient with a bright spot (float)
//   test.exr  ref with a noisy patch and a shifted colour (half, plus a "variance" channel)
//   nan.exr   ref with one NaN and one +Inf pixel
//   flat.exr  64x48 of radiance 2 in R, G, B (for --exact)
//   small.exr 32x24 (a size mismatch)
#include "gi/image/exr.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

using lumina::image::ExrPixelType;
using lumina::image::ExrWriteOptions;
using lumina::image::Image;

namespace {

Image gradient(uint32_t w, uint32_t h) {
    Image image = Image::rgba(w, h);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const float u = float(x) / float(w);
            const float v = float(y) / float(h);
            const float spot = (x > 40 && x < 46 && y > 10 && y < 16) ? 20.0f : 0.0f;
            image.setRgb(x, y, {0.05f + 1.5f * u + spot, 0.1f + 0.8f * v + spot, 0.3f + 0.2f * u * v + spot});
        }
    }
    return image;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: make_compare_inputs DIR\n";
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    const Image reference = gradient(64, 48);
    lumina::image::writeExr(dir / "ref.exr", reference);

    Image test = reference;
    uint32_t state = 12345;
    for (uint32_t y = 8; y < 24; ++y) {
        for (uint32_t x = 8; x < 24; ++x) {
            state = state * 1664525u + 1013904223u;
            const float noise = float(state >> 8) / float(1u << 24) - 0.5f;
            auto rgb = test.rgbAt(x, y);
            test.setRgb(x, y, {rgb.r * (1.0f + noise), rgb.g, rgb.b * 1.2f});
        }
    }
    test.addChannel("variance", 0.01f);
    ExrWriteOptions half;
    half.pixelType = ExrPixelType::Half;
    lumina::image::writeExr(dir / "test.exr", test, half);

    Image bad = reference;
    bad.set("G", 3, 4, std::numeric_limits<float>::quiet_NaN());
    bad.set("R", 5, 6, std::numeric_limits<float>::infinity());
    lumina::image::writeExr(dir / "nan.exr", bad);

    lumina::image::writeExr(dir / "small.exr", gradient(32, 24));

    Image flat = Image::rgb(64, 48);
    for (uint32_t y = 0; y < 48; ++y) {
        for (uint32_t x = 0; x < 64; ++x) {
            flat.setRgb(x, y, {2.0f, 2.0f, 2.0f});
        }
    }
    lumina::image::writeExr(dir / "flat.exr", flat);
    return 0;
}
