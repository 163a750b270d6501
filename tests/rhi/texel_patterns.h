#pragma once
// Texel data the tests can upload to any format and expect back bit for bit: every value is
// a valid, finite texel of its format (depth in [0, 1], no NaN or Inf half floats), and the
// pattern differs per seed, so layers, slices and mips cannot be confused.
#include "rhi/format.h"
#include "rhi/resource.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lumina::test {

std::vector<uint8_t> texelPattern(rhi::Format format, size_t texels, uint32_t seed);

// IEEE half-float bits of a float (round to nearest even), for expectations on 16F targets.
uint16_t floatToHalf(float value);
float halfToFloat(uint16_t bits);

} // namespace lumina::test
