#include "gi/deferred/buffer_readback.h"

#include "gi/deferred/deferred_renderer.h"
#include "gi/image/exr.h"
#include "gi/image/png.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>

namespace lumina::gi {

namespace {

// IEEE 754 binary16 to float, subnormals, infinities and NaN included.
float halfToFloat(uint16_t bits) {
    const uint32_t sign = uint32_t(bits & 0x8000u) << 16;
    const uint32_t exponent = (bits >> 10) & 0x1Fu;
    const uint32_t mantissa = bits & 0x3FFu;
    if (exponent == 0) {
        const float magnitude = std::ldexp(float(mantissa), -24);
        return sign ? -magnitude : magnitude;
    }
    if (exponent == 31) {
        return std::bit_cast<float>(sign | 0x7F800000u | (mantissa << 13));
    }
    return std::bit_cast<float>(sign | ((exponent + 112) << 23) | (mantissa << 13));
}

const char* kRgba[4] = {"R", "G", "B", "A"};

} // namespace

image::Image readTextureImage(rhi::IDevice& device, rhi::ITexture& texture, uint32_t arrayLayer) {
    const rhi::TextureDesc& desc = texture.desc();
    const std::vector<uint8_t> bytes = rhi::readTexture(device, texture, {0, arrayLayer});
    const size_t pixels = size_t(desc.width) * desc.height;
    const rhi::FormatInfo& info = rhi::formatInfo(desc.format);
    auto value = [&](size_t texel, uint32_t channel) -> float {
        const uint8_t* at = bytes.data() + texel * info.bytesPerTexel;
        switch (desc.format) {
        case rhi::Format::RGBA8_UNORM:
            return float(at[channel]) / 255.0f;
        case rhi::Format::RG16_FLOAT:
        case rhi::Format::RGBA16_FLOAT: {
            uint16_t half = 0;
            std::memcpy(&half, at + 2 * channel, 2);
            return halfToFloat(half);
        }
        case rhi::Format::RGBA32_FLOAT:
        case rhi::Format::R32_FLOAT:
        case rhi::Format::D32_FLOAT: {
            float f = 0.0f;
            std::memcpy(&f, at + 4 * channel, 4);
            return f;
        }
        default:
            throw rhi::Error("readTextureImage: '" + texture.debugName() + "' has format " +
                             std::string(info.name) + ", which has no image conversion");
        }
    };
    image::Image out(desc.width, desc.height,
                     info.channels == 4 ? std::vector<std::string>{"R", "G", "B", "A"}
                                        : std::vector<std::string>{"R", "G", "B"});
    // One channel fills R, G and B; two fill R and G (B stays 0).
    for (uint32_t c = 0; c < (info.channels == 4 ? 4u : 3u); ++c) {
        std::span<float> plane = out.channel(kRgba[c]);
        if (info.channels == 2 && c == 2) {
            continue;
        }
        const uint32_t source = info.channels == 1 ? 0 : c;
        for (size_t i = 0; i < pixels; ++i) {
            plane[i] = value(i, source);
        }
    }
    return out;
}

image::Image readCubeStrip(rhi::IDevice& device, rhi::ITexture& cubes, uint32_t cube) {
    const uint32_t size = cubes.desc().width;
    image::Image strip(size * LUMINA_CUBE_FACE_COUNT, size);
    for (uint32_t face = 0; face < LUMINA_CUBE_FACE_COUNT; ++face) {
        const image::Image faceImage = readTextureImage(device, cubes, cube * LUMINA_CUBE_FACE_COUNT + face);
        for (const char* channel : {"R", "G", "B"}) {
            const std::span<const float> from = faceImage.channel(channel);
            const std::span<float> to = strip.channel(channel);
            for (uint32_t y = 0; y < size; ++y) {
                std::copy_n(from.begin() + size_t(y) * size, size,
                            to.begin() + size_t(y) * strip.width() + size_t(face) * size);
            }
        }
    }
    return strip;
}

image::Image displayImage(const image::Image& rgba8) {
    image::Image out = image::Image::rgb(rgba8.width(), rgba8.height());
    for (const char* channel : {"R", "G", "B"}) {
        std::ranges::copy(rgba8.channel(channel), out.channel(channel).begin());
    }
    return out;
}

namespace {

// A view of data that is not radiance: each of R, G, B mapped linearly from [lo, hi] to [0, 1].
image::Image rescaled(const image::Image& source, float lo, float hi) {
    image::Image out = image::Image::rgb(source.width(), source.height());
    for (const char* channel : {"R", "G", "B"}) {
        const std::span<const float> from = source.channel(channel);
        const std::span<float> to = out.channel(channel);
        for (size_t i = 0; i < from.size(); ++i) {
            to[i] = std::clamp((from[i] - lo) / (hi - lo), 0.0f, 1.0f);
        }
    }
    return out;
}

// Range of R, G, B over pixels where `mask` (may be empty) is positive; [0, 1] when empty.
std::pair<float, float> valueRange(const image::Image& source, std::span<const float> mask) {
    float lo = std::numeric_limits<float>::max(), hi = -std::numeric_limits<float>::max();
    for (const char* channel : {"R", "G", "B"}) {
        const std::span<const float> values = source.channel(channel);
        for (size_t i = 0; i < values.size(); ++i) {
            if ((mask.empty() || mask[i] > 0.0f) && std::isfinite(values[i])) {
                lo = std::min(lo, values[i]);
                hi = std::max(hi, values[i]);
            }
        }
    }
    return lo < hi ? std::pair{lo, hi} : std::pair{0.0f, 1.0f};
}

} // namespace

std::vector<std::filesystem::path> dumpDeferredBuffers(rhi::IDevice& device, const DeferredRenderer& renderer,
                                                       const std::filesystem::path& directory,
                                                       const image::DisplayOptions& display) {
    std::filesystem::create_directories(directory);
    std::vector<std::filesystem::path> written;
    auto exr = [&](const std::string& name, const image::Image& image) {
        written.push_back(directory / (name + ".exr"));
        image::writeExr(written.back(), image);
    };
    auto png = [&](const std::string& name, const image::Image& image) {
        written.push_back(directory / (name + ".png"));
        image::writeDisplayPng(written.back(), image);
    };
    const image::DisplayOptions clamp{.exposureEv = 0.0f, .tonemap = image::Tonemap::Clamp};

    const GBuffer& gbuffer = renderer.gbuffer();
    const image::Image albedo = readTextureImage(device, *gbuffer.albedo);
    exr("gbuffer_albedo", albedo);
    png("gbuffer_albedo", image::toDisplay(albedo, clamp));
    const image::Image normal = readTextureImage(device, *gbuffer.normal);
    exr("gbuffer_normal", normal);
    png("gbuffer_normal", rescaled(normal, -1.0f, 1.0f));
    const image::Image material = readTextureImage(device, *gbuffer.material);
    exr("gbuffer_material", material);
    png("gbuffer_material_emission", image::toDisplay(material, display));
    const image::Image position = readTextureImage(device, *gbuffer.position);
    exr("gbuffer_position", position);
    const auto [posLo, posHi] = valueRange(position, normal.channel("A"));
    png("gbuffer_position", rescaled(position, posLo, posHi));
    const image::Image depth = readTextureImage(device, *gbuffer.depth);
    exr("gbuffer_depth", depth);
    const auto [depthLo, depthHi] = valueRange(depth, normal.channel("A"));
    png("gbuffer_depth", rescaled(depth, depthLo, depthHi));

    if (const rhi::TextureHandle sun = renderer.sunShadowMap()) {
        const image::Image map = readTextureImage(device, *sun);
        exr("sun_shadow", map);
        png("sun_shadow", rescaled(map, 0.0f, 1.0f));
    }
    if (const rhi::TextureHandle cubes = renderer.pointShadowMaps()) {
        for (uint32_t cube = 0; cube < renderer.pointShadowCubes(); ++cube) {
            const image::Image strip = readCubeStrip(device, *cubes, cube);
            const std::string name = "point_shadow_" + std::to_string(cube);
            exr(name, strip);
            png(name, rescaled(strip, 0.0f, 1.0f));
        }
    }

    const image::Image direct = readTextureImage(device, *renderer.direct());
    exr("direct", direct);
    png("direct", image::toDisplay(direct, display));
    exr("hdr", readTextureImage(device, *renderer.hdr()));
    png("ldr", displayImage(readTextureImage(device, *renderer.ldr())));
    return written;
}

} // namespace lumina::gi
