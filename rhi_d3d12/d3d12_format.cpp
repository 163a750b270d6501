#include "rhi_d3d12/d3d12_format.h"

#include "rhi/error.h"

#include <array>
#include <string>

namespace lumina::d3d12 {

namespace {
constexpr DxgiFormats colour(DXGI_FORMAT format) {
    return {format, format, format, format, DXGI_FORMAT_UNKNOWN};
}

constexpr std::array<DxgiFormats, size_t(rhi::Format::Count)> kFormats = {{
    {DXGI_FORMAT_UNKNOWN, DXGI_FORMAT_UNKNOWN, DXGI_FORMAT_UNKNOWN, DXGI_FORMAT_UNKNOWN, DXGI_FORMAT_UNKNOWN},
    colour(DXGI_FORMAT_R8_UNORM),
    colour(DXGI_FORMAT_R8G8B8A8_UNORM),
    // sRGB formats take no UAVs in D3D12
    {DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, DXGI_FORMAT_UNKNOWN,
     DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, DXGI_FORMAT_UNKNOWN},
    colour(DXGI_FORMAT_R16_FLOAT),
    colour(DXGI_FORMAT_R16G16_FLOAT),
    colour(DXGI_FORMAT_R16G16B16A16_FLOAT),
    colour(DXGI_FORMAT_R32_FLOAT),
    colour(DXGI_FORMAT_R32G32_FLOAT),
    colour(DXGI_FORMAT_R32G32B32A32_FLOAT),
    colour(DXGI_FORMAT_R32_UINT),
    colour(DXGI_FORMAT_R32G32_UINT),
    colour(DXGI_FORMAT_R32G32B32A32_UINT),
    {DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_R32_FLOAT, DXGI_FORMAT_UNKNOWN, DXGI_FORMAT_UNKNOWN,
     DXGI_FORMAT_D32_FLOAT},
}};
} // namespace

const DxgiFormats& dxgiFormats(rhi::Format format) {
    const auto index = size_t(format);
    if (format == rhi::Format::Unknown || index >= kFormats.size()) {
        throw rhi::Error("D3D12: no DXGI format for rhi::Format value " + std::to_string(index));
    }
    return kFormats[index];
}

} // namespace lumina::d3d12
