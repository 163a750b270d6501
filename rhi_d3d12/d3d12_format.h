#pragma once
// rhi::Format to the DXGI formats of a resource and of each kind of view of it.
#include "rhi/format.h"
#include "rhi_d3d12/d3d12_headers.h"

namespace lumina::d3d12 {

struct DxgiFormats {
    DXGI_FORMAT resource; // depth formats are typeless so that they can be sampled
    DXGI_FORMAT srv;
    DXGI_FORMAT uav; // DXGI_FORMAT_UNKNOWN: no typed UAV (sRGB, depth)
    DXGI_FORMAT rtv; // DXGI_FORMAT_UNKNOWN: not a colour target (depth)
    DXGI_FORMAT dsv; // DXGI_FORMAT_UNKNOWN: not a depth format
};

// Throws rhi::Error for Format::Unknown.
const DxgiFormats& dxgiFormats(rhi::Format format);

} // namespace lumina::d3d12
