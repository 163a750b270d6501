#include "rhi_d3d12/d3d12_adapter.h"

#include "rhi_d3d12/d3d12_backend.h"
#include "rhi_d3d12/d3d12_check.h"

#include <algorithm>
#include <cstdio>
#include <iterator>

namespace lumina::d3d12 {

namespace {

std::string featureLevelName(D3D_FEATURE_LEVEL level) {
    char text[16];
    std::snprintf(text, sizeof text, "%u_%u", (unsigned(level) >> 12) & 0xF, (unsigned(level) >> 8) & 0xF);
    return text;
}

std::string shaderModelName(uint32_t model) {
    char text[16];
    std::snprintf(text, sizeof text, "%u.%u", model >> 4, model & 0xF);
    return text;
}

std::string driverVersion(IDXGIAdapter1* adapter) {
    LARGE_INTEGER version{};
    if (FAILED(adapter->CheckInterfaceSupport(__uuidof(IDXGIDevice), &version))) {
        return "unknown";
    }
    const auto part = [&](int shift) { return unsigned((uint64_t(version.QuadPart) >> shift) & 0xFFFF); };
    char text[48];
    std::snprintf(text, sizeof text, "%u.%u.%u.%u", part(48), part(32), part(16), part(0));
    return text;
}

} // namespace

ComPtr<IDXGIFactory4> createFactory(bool debug) {
    ComPtr<IDXGIFactory4> factory;
    if (debug && SUCCEEDED(CreateDXGIFactory2(DXGI_CREATE_FACTORY_DEBUG, IID_PPV_ARGS(&factory)))) {
        return factory;
    }
    check(CreateDXGIFactory2(0, IID_PPV_ARGS(&factory)), "CreateDXGIFactory2");
    return factory;
}

uint32_t highestShaderModel(ID3D12Device* device) {
    // Runtimes reject models newer than they know: ask from the newest down.
    for (uint32_t model : {0x67u, 0x66u, 0x65u, 0x64u, 0x63u, 0x62u, 0x61u, 0x60u, 0x51u}) {
        D3D12_FEATURE_DATA_SHADER_MODEL data{static_cast<D3D_SHADER_MODEL>(model)};
        if (SUCCEEDED(device->CheckFeatureSupport(D3D12_FEATURE_SHADER_MODEL, &data, sizeof data))) {
            return static_cast<uint32_t>(data.HighestShaderModel);
        }
    }
    return 0x51;
}

D3D_FEATURE_LEVEL highestFeatureLevel(ID3D12Device* device) {
    const D3D_FEATURE_LEVEL levels[] = {D3D_FEATURE_LEVEL_12_2, D3D_FEATURE_LEVEL_12_1,
                                        D3D_FEATURE_LEVEL_12_0, D3D_FEATURE_LEVEL_11_1,
                                        D3D_FEATURE_LEVEL_11_0};
    D3D12_FEATURE_DATA_FEATURE_LEVELS data{};
    data.NumFeatureLevels = static_cast<UINT>(std::size(levels));
    data.pFeatureLevelsRequested = levels;
    if (SUCCEEDED(device->CheckFeatureSupport(D3D12_FEATURE_FEATURE_LEVELS, &data, sizeof data))) {
        return data.MaxSupportedFeatureLevel;
    }
    return kMinimumFeatureLevel;
}

std::vector<AdapterEntry> enumerateAdapters(IDXGIFactory4* factory) {
    std::vector<ComPtr<IDXGIAdapter1>> adapters;
    ComPtr<IDXGIFactory6> factory6;
    if (SUCCEEDED(factory->QueryInterface(IID_PPV_ARGS(&factory6)))) {
        ComPtr<IDXGIAdapter1> adapter;
        for (UINT i = 0; SUCCEEDED(factory6->EnumAdapterByGpuPreference(
                 i, DXGI_GPU_PREFERENCE_HIGH_PERFORMANCE, IID_PPV_ARGS(&adapter)));
             ++i) {
            adapters.push_back(adapter);
        }
    }
    if (adapters.empty()) {
        ComPtr<IDXGIAdapter1> adapter;
        for (UINT i = 0; factory->EnumAdapters1(i, &adapter) != DXGI_ERROR_NOT_FOUND; ++i) {
            adapters.push_back(adapter);
        }
    }
    std::vector<AdapterEntry> entries;
    for (const ComPtr<IDXGIAdapter1>& adapter : adapters) {
        DXGI_ADAPTER_DESC1 desc{};
        if (FAILED(adapter->GetDesc1(&desc))) {
            continue;
        }
        ComPtr<ID3D12Device> device;
        if (FAILED(D3D12CreateDevice(adapter.Get(), kMinimumFeatureLevel, IID_PPV_ARGS(&device)))) {
            continue; // no D3D12 on this adapter
        }
        AdapterEntry entry;
        entry.adapter = adapter;
        rhi::AdapterInfo& info = entry.info;
        info.name = toUtf8(desc.Description);
        info.driver = driverVersion(adapter.Get());
        info.apiVersion = "FL " + featureLevelName(highestFeatureLevel(device.Get())) + ", SM " +
                          shaderModelName(highestShaderModel(device.Get()));
        info.vendorId = desc.VendorId;
        info.deviceId = desc.DeviceId;
        info.dedicatedMemoryBytes = desc.DedicatedVideoMemory;
        if (desc.Flags & DXGI_ADAPTER_FLAG_SOFTWARE) {
            info.type = rhi::AdapterType::Cpu;
        } else {
            D3D12_FEATURE_DATA_ARCHITECTURE architecture{};
            const bool known = SUCCEEDED(
                device->CheckFeatureSupport(D3D12_FEATURE_ARCHITECTURE, &architecture, sizeof architecture));
            info.type = !known             ? rhi::AdapterType::Other
                        : architecture.UMA ? rhi::AdapterType::Integrated
                                           : rhi::AdapterType::Discrete;
        }
        entries.push_back(std::move(entry));
    }
    std::stable_partition(entries.begin(), entries.end(),
                          [](const AdapterEntry& entry) { return entry.info.type != rhi::AdapterType::Cpu; });
    for (size_t i = 0; i < entries.size(); ++i) {
        entries[i].info.index = static_cast<uint32_t>(i);
    }
    return entries;
}

std::vector<rhi::AdapterInfo> listAdapters() {
    std::vector<rhi::AdapterInfo> infos;
    for (AdapterEntry& entry : enumerateAdapters(createFactory(false).Get())) {
        infos.push_back(std::move(entry.info));
    }
    return infos;
}

} // namespace lumina::d3d12
