#include "tests/rhi/texel_patterns.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace lumina::test {

namespace {

uint32_t hash(uint32_t value) {
    // PCG output permutation: cheap and well mixed.
    const uint32_t state = value * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Finite, normal, positive half floats: exponents 1..30.
constexpr uint32_t kSmallestNormalHalf = 0x0400;
constexpr uint32_t kLargestFiniteHalf = 0x7BFF;
// Float texels are multiples of 1/8 below 2^14: exact in float32, easy to read in a failure.
constexpr uint32_t kFloatSteps = 1u << 17;
constexpr float kFloatStep = 0.125f;
// Depth in [0, 1] in steps of 1/1000 (D32 copies reject values outside [0, 1]).
constexpr uint32_t kDepthSteps = 1000;

} // namespace

std::vector<uint8_t> texelPattern(rhi::Format format, size_t texels, uint32_t seed) {
    const rhi::FormatInfo& info = rhi::formatInfo(format);
    const uint32_t channelBytes = info.bytesPerTexel / info.channels;
    std::vector<uint8_t> bytes(texels * info.bytesPerTexel);
    for (size_t texel = 0; texel < texels; ++texel) {
        for (uint32_t channel = 0; channel < info.channels; ++channel) {
            const uint32_t v = hash(seed * 0x9E3779B9u ^ hash(static_cast<uint32_t>(texel * 4 + channel)));
            uint8_t* out = bytes.data() + texel * info.bytesPerTexel + channel * channelBytes;
            if (info.kind == rhi::FormatKind::Depth) {
                const float depth = static_cast<float>(v % (kDepthSteps + 1)) / kDepthSteps;
                std::memcpy(out, &depth, 4);
            } else if (info.kind == rhi::FormatKind::Float && channelBytes == 2) {
                const auto half = static_cast<uint16_t>(kSmallestNormalHalf +
                                                        v % (kLargestFiniteHalf - kSmallestNormalHalf));
                std::memcpy(out, &half, 2);
            } else if (info.kind == rhi::FormatKind::Float) {
                const float value = static_cast<float>(v % kFloatSteps) * kFloatStep;
                std::memcpy(out, &value, 4);
            } else {
                std::memcpy(out, &v, channelBytes); // unorm bytes and uints: any bits are valid
            }
        }
    }
    return bytes;
}

uint16_t floatToHalf(float value) {
    const uint32_t bits = std::bit_cast<uint32_t>(value);
    const uint32_t sign = (bits >> 16) & 0x8000;
    const int32_t exponent = static_cast<int32_t>((bits >> 23) & 0xFF) - 127 + 15;
    uint32_t mantissa = bits & 0x7FFFFF;
    if (exponent >= 31) {
        return static_cast<uint16_t>(sign | 0x7C00); // overflow to infinity (NaN not needed here)
    }
    if (exponent <= 0) {
        if (exponent < -10) {
            return static_cast<uint16_t>(sign);
        }
        mantissa |= 0x800000;
        const uint32_t shift = static_cast<uint32_t>(14 - exponent);
        uint32_t half = mantissa >> shift;
        const uint32_t rest = mantissa & ((1u << shift) - 1);
        const uint32_t halfway = 1u << (shift - 1);
        if (rest > halfway || (rest == halfway && (half & 1))) {
            ++half;
        }
        return static_cast<uint16_t>(sign | half);
    }
    uint32_t half = (static_cast<uint32_t>(exponent) << 10) | (mantissa >> 13);
    const uint32_t rest = mantissa & 0x1FFF;
    if (rest > 0x1000 || (rest == 0x1000 && (half & 1))) {
        ++half; // may carry into the exponent, which is the correct rounding
    }
    return static_cast<uint16_t>(sign | half);
}

float halfToFloat(uint16_t bits) {
    const uint32_t sign = (bits & 0x8000u) << 16;
    const uint32_t exponent = (bits >> 10) & 0x1F;
    const uint32_t mantissa = bits & 0x3FF;
    if (exponent == 0) {
        const float value = std::ldexp(static_cast<float>(mantissa), -24);
        return sign ? -value : value;
    }
    if (exponent == 31) {
        return std::bit_cast<float>(sign | 0x7F800000u | (mantissa << 13));
    }
    return std::bit_cast<float>(sign | ((exponent - 15 + 127) << 23) | (mantissa << 13));
}

} // namespace lumina::test
