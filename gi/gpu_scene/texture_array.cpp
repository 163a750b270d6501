// Material textures into one 2D array: every texture resampled to a shared square layer
// size, mips box-filtered. Filtering happens on linear values (sRGB decoded first, alpha
// as is) so that mips keep the average brightness the path tracer sees.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "gi/gpu_scene/gpu_scene.h"

namespace lumina::gi {

namespace {

float srgbToLinear(uint8_t value) {
    const float c = value / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

uint8_t linearToSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<uint8_t>(std::lround(s * 255.0f));
}

// Linear RGBA of one square layer.
using LinearLayer = std::vector<std::array<float, 4>>;

LinearLayer decode(const scene::Texture& texture) {
    std::array<float, 256> lut{};
    for (int i = 0; i < 256; ++i) {
        lut[i] = srgbToLinear(static_cast<uint8_t>(i));
    }
    LinearLayer out(size_t(texture.width) * texture.height);
    for (size_t i = 0; i < out.size(); ++i) {
        const uint8_t* p = &texture.rgba8[i * 4];
        out[i] = {lut[p[0]], lut[p[1]], lut[p[2]], p[3] / 255.0f};
    }
    return out;
}

// Bilinear resample with wrap addressing (glTF's default sampler) to size x size.
LinearLayer resample(const LinearLayer& src, uint32_t width, uint32_t height, uint32_t size) {
    LinearLayer out(size_t(size) * size);
    auto at = [&](int x, int y) -> const std::array<float, 4>& {
        x = (x % int(width) + int(width)) % int(width);
        y = (y % int(height) + int(height)) % int(height);
        return src[size_t(y) * width + x];
    };
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            const float sx = (x + 0.5f) * width / size - 0.5f;
            const float sy = (y + 0.5f) * height / size - 0.5f;
            const int x0 = int(std::floor(sx));
            const int y0 = int(std::floor(sy));
            const float fx = sx - x0;
            const float fy = sy - y0;
            auto& texel = out[size_t(y) * size + x];
            for (int c = 0; c < 4; ++c) {
                const float top = at(x0, y0)[c] * (1 - fx) + at(x0 + 1, y0)[c] * fx;
                const float bottom = at(x0, y0 + 1)[c] * (1 - fx) + at(x0 + 1, y0 + 1)[c] * fx;
                texel[c] = top * (1 - fy) + bottom * fy;
            }
        }
    }
    return out;
}

LinearLayer halve(const LinearLayer& src, uint32_t size) {
    const uint32_t half = std::max(1u, size / 2);
    LinearLayer out(size_t(half) * half);
    for (uint32_t y = 0; y < half; ++y) {
        for (uint32_t x = 0; x < half; ++x) {
            auto& texel = out[size_t(y) * half + x];
            for (int c = 0; c < 4; ++c) {
                float sum = 0;
                for (uint32_t dy = 0; dy < 2; ++dy) {
                    for (uint32_t dx = 0; dx < 2; ++dx) {
                        sum += src[size_t(std::min(2 * y + dy, size - 1)) * size + std::min(2 * x + dx, size - 1)][c];
                    }
                }
                texel[c] = sum / 4;
            }
        }
    }
    return out;
}

void encodeInto(const LinearLayer& layer, std::vector<uint8_t>& out) {
    for (const auto& texel : layer) {
        out.push_back(linearToSrgb(texel[0]));
        out.push_back(linearToSrgb(texel[1]));
        out.push_back(linearToSrgb(texel[2]));
        out.push_back(static_cast<uint8_t>(std::lround(std::clamp(texel[3], 0.0f, 1.0f) * 255.0f)));
    }
}

} // namespace

TextureArrayData packTextures(const scene::Scene& scene, uint32_t maxLayerSize) {
    TextureArrayData data;
    uint32_t largest = 1;
    for (const scene::Texture& texture : scene.textures) {
        largest = std::max({largest, texture.width, texture.height});
    }
    data.layerSize = std::min(std::bit_ceil(largest), std::bit_floor(std::max(1u, maxLayerSize)));
    data.layers = std::max<uint32_t>(1, uint32_t(scene.textures.size()));
    const uint32_t mipCount = std::bit_width(data.layerSize);
    data.mips.resize(mipCount);

    std::vector<LinearLayer> layers;
    if (scene.textures.empty()) {
        layers.push_back(LinearLayer(1, {1.0f, 1.0f, 1.0f, 1.0f})); // white: "no texture" multiplies by one
    }
    for (const scene::Texture& texture : scene.textures) {
        layers.push_back(resample(decode(texture), texture.width, texture.height, data.layerSize));
    }
    for (LinearLayer& layer : layers) {
        uint32_t size = data.layerSize;
        for (uint32_t mip = 0; mip < mipCount; ++mip) {
            encodeInto(layer, data.mips[mip]);
            if (mip + 1 < mipCount) {
                layer = halve(layer, size);
                size = std::max(1u, size / 2);
            }
        }
    }
    return data;
}

} // namespace lumina::gi
