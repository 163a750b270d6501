#pragma once
// The one place that includes the Windows, D3D12 and DXGI headers.
//
// D3D12 comes from DirectX-Headers (vcpkg's directx-headers on MSVC, Debian's
// directx-headers-dev on MinGW-w64) when the build found it, as <directx/d3d12.h>: MinGW-w64
// 10's own d3d12.h predates DRED, ID3D12Debug1 and shader model 6.x. <dxguids/dxguids.h>
// supplies __uuidof for those newer interfaces on compilers without __declspec(uuid).
// Without DirectX-Headers (MSVC with the Windows SDK alone) the SDK's d3d12.h is used.
#ifndef NOMINMAX
#define NOMINMAX
#endif
// Not WIN32_LEAN_AND_MEAN: DirectX-Headers' d3d12.h asks for a newer rpcndr.h than MinGW-w64
// ships, a check that only passes when <windows.h> has already pulled rpcndr.h in.
#include <windows.h>
// winspool.h's DeviceCapabilities macro would rename rhi::DeviceCapabilities.
#undef DeviceCapabilities

#if LUMINA_D3D12_DIRECTX_HEADERS
#include <directx/d3d12.h>
#include <directx/d3d12sdklayers.h>
#else
#include <d3d12.h>
#include <d3d12sdklayers.h>
#endif
#include <dxgi1_6.h>
#if LUMINA_D3D12_DIRECTX_HEADERS
#include <dxguids/dxguids.h>
#endif

#include <wrl/client.h>

namespace lumina::d3d12 {

template <typename T>
using ComPtr = Microsoft::WRL::ComPtr<T>;

// Methods that return a structure. DirectX-Headers declare them with the structure returned
// only for MSVC; for other Windows compilers with an out-parameter, which is MSVC's ABI for
// member functions returning aggregates (GCC would otherwise disagree with the runtime).
#if defined(_MSC_VER) || !defined(_WIN32)
inline D3D12_RESOURCE_DESC resourceDesc(ID3D12Resource* resource) {
    return resource->GetDesc();
}
inline D3D12_CPU_DESCRIPTOR_HANDLE cpuHeapStart(ID3D12DescriptorHeap* heap) {
    return heap->GetCPUDescriptorHandleForHeapStart();
}
inline D3D12_GPU_DESCRIPTOR_HANDLE gpuHeapStart(ID3D12DescriptorHeap* heap) {
    return heap->GetGPUDescriptorHandleForHeapStart();
}
inline D3D12_RESOURCE_ALLOCATION_INFO allocationInfo(ID3D12Device* device, const D3D12_RESOURCE_DESC& desc) {
    return device->GetResourceAllocationInfo(0, 1, &desc);
}
inline D3D12_HEAP_PROPERTIES customHeapProperties(ID3D12Device* device, D3D12_HEAP_TYPE type) {
    return device->GetCustomHeapProperties(0, type);
}
#else
inline D3D12_RESOURCE_DESC resourceDesc(ID3D12Resource* resource) {
    D3D12_RESOURCE_DESC desc;
    resource->GetDesc(&desc);
    return desc;
}
inline D3D12_CPU_DESCRIPTOR_HANDLE cpuHeapStart(ID3D12DescriptorHeap* heap) {
    D3D12_CPU_DESCRIPTOR_HANDLE handle;
    heap->GetCPUDescriptorHandleForHeapStart(&handle);
    return handle;
}
inline D3D12_GPU_DESCRIPTOR_HANDLE gpuHeapStart(ID3D12DescriptorHeap* heap) {
    D3D12_GPU_DESCRIPTOR_HANDLE handle;
    heap->GetGPUDescriptorHandleForHeapStart(&handle);
    return handle;
}
inline D3D12_RESOURCE_ALLOCATION_INFO allocationInfo(ID3D12Device* device, const D3D12_RESOURCE_DESC& desc) {
    D3D12_RESOURCE_ALLOCATION_INFO info;
    device->GetResourceAllocationInfo(&info, 0, 1, &desc);
    return info;
}
inline D3D12_HEAP_PROPERTIES customHeapProperties(ID3D12Device* device, D3D12_HEAP_TYPE type) {
    D3D12_HEAP_PROPERTIES properties;
    device->GetCustomHeapProperties(&properties, 0, type);
    return properties;
}
#endif

} // namespace lumina::d3d12
