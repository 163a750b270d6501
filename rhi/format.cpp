#include "rhi/format.h"

#include <array>

#include "rhi/error.h"

namespace lumina::rhi {

namespace {
constexpr std::array<FormatInfo, static_cast<size_t>(Format::Count)> kFormats = {{
    {Format::Unknown, "Unknown", 0, 0, FormatKind::Unorm},
    {Format::R8_UNORM, "R8_UNORM", 1, 1, FormatKind::Unorm},
    {Format::RGBA8_UNORM, "RGBA8_UNORM", 4, 4, FormatKind::Unorm},
    {Format::RGBA8_SRGB, "RGBA8_SRGB", 4, 4, FormatKind::Unorm},
    {Format::R16_FLOAT, "R16_FLOAT", 2, 1, FormatKind::Float},
    {Format::RG16_FLOAT, "RG16_FLOAT", 4, 2, FormatKind::Float},
    {Format::RGBA16_FLOAT, "RGBA16_FLOAT", 8, 4, FormatKind::Float},
    {Format::R32_FLOAT, "R32_FLOAT", 4, 1, FormatKind::Float},
    {Format::RG32_FLOAT, "RG32_FLOAT", 8, 2, FormatKind::Float},
    {Format::RGBA32_FLOAT, "RGBA32_FLOAT", 16, 4, FormatKind::Float},
    {Format::R32_UINT, "R32_UINT", 4, 1, FormatKind::Uint},
    {Format::RG32_UINT, "RG32_UINT", 8, 2, FormatKind::Uint},
    {Format::RGBA32_UINT, "RGBA32_UINT", 16, 4, FormatKind::Uint},
    {Format::D32_FLOAT, "D32_FLOAT", 4, 1, FormatKind::Depth},
}};
} // namespace

const FormatInfo& formatInfo(Format format) {
    const auto index = static_cast<size_t>(format);
    if (index >= kFormats.size()) {
        throw Error("formatInfo: invalid format value " + std::to_string(index));
    }
    return kFormats[index];
}

} // namespace lumina::rhi
