#pragma once
// The Direct3D 12 backend's public entry points; app/backends.cpp picks them with --api d3d12.
#include "rhi/device.h"

#include <vector>

namespace lumina::d3d12 {

// Every DXGI adapter that can create a D3D12 device (feature level 11_0), in DXGI's order of
// preference (high performance first); software adapters (WARP) are listed last.
std::vector<rhi::AdapterInfo> listAdapters();

// A device on adapter desc.adapterIndex. desc.validation enables the debug layer, and
// desc.gpuBasedValidation its GPU-based validation; DRED (breadcrumbs and page-fault data for
// the device-removed report) is always enabled where the runtime offers it.
rhi::DeviceHandle createDevice(const rhi::DeviceDesc& desc);

} // namespace lumina::d3d12
