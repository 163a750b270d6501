#pragma once
#include <cstdint>
#include <string_view>

namespace lumina::rhi {

enum class Format : uint8_t {
    Unknown,
    R8_UNORM,
    RGBA8_UNORM,
    RGBA8_SRGB,
    R16_FLOAT,
    RG16_FLOAT,
    RGBA16_FLOAT,
    R32_FLOAT,
    RG32_FLOAT,
    RGBA32_FLOAT,
    R32_UINT,
    RG32_UINT,
    RGBA32_UINT,
    D32_FLOAT,
    Count
};

enum class FormatKind : uint8_t { Unorm, Float, Uint, Depth };

struct FormatInfo {
    Format format;
    std::string_view name;
    uint32_t bytesPerTexel;
    uint32_t channels;
    FormatKind kind;
};

const FormatInfo& formatInfo(Format format);
inline bool isDepthFormat(Format format) { return formatInfo(format).kind == FormatKind::Depth; }

} // namespace lumina::rhi
