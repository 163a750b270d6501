#pragma once
// DXGI adapters that can run D3D12, and what each offers.
#include "rhi/device.h"
#include "rhi_d3d12/d3d12_headers.h"

#include <cstdint>
#include <vector>

namespace lumina::d3d12 {

// Feature level every Lumina device needs.
constexpr D3D_FEATURE_LEVEL kMinimumFeatureLevel = D3D_FEATURE_LEVEL_11_0;

struct AdapterEntry {
    ComPtr<IDXGIAdapter1> adapter;
    rhi::AdapterInfo info;
};

// debug: DXGI's debug factory where installed (falls back to the plain one).
ComPtr<IDXGIFactory4> createFactory(bool debug);
// High-performance adapters first where DXGI 1.6 can say; software adapters last.
std::vector<AdapterEntry> enumerateAdapters(IDXGIFactory4* factory);

// 0x51 for shader model 5.1, 0x60..0x6F for 6.x.
uint32_t highestShaderModel(ID3D12Device* device);
D3D_FEATURE_LEVEL highestFeatureLevel(ID3D12Device* device);

} // namespace lumina::d3d12
