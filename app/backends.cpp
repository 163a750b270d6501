#include "app/backends.h"

#include <string>

#include "rhi/error.h"

#if LUMINA_HAS_VULKAN
#include "rhi_vulkan/vk_backend.h"
#endif
#if LUMINA_HAS_D3D12
#include "rhi_d3d12/d3d12_backend.h"
#endif

namespace lumina::app {

std::vector<rhi::Api> compiledApis() {
    std::vector<rhi::Api> apis;
#if LUMINA_HAS_VULKAN
    apis.push_back(rhi::Api::Vulkan);
#endif
#if LUMINA_HAS_D3D12
    apis.push_back(rhi::Api::D3D12);
#endif
    return apis;
}

namespace {
[[noreturn]] void notCompiled(rhi::Api api) {
    throw rhi::Error("the " + std::string(rhi::apiName(api)) + " backend is not compiled into this build");
}
} // namespace

std::vector<rhi::AdapterInfo> listAdapters(rhi::Api api) {
    switch (api) {
    case rhi::Api::Vulkan:
#if LUMINA_HAS_VULKAN
        return vulkan::listAdapters();
#else
        break;
#endif
    case rhi::Api::D3D12:
#if LUMINA_HAS_D3D12
        return d3d12::listAdapters();
#else
        break;
#endif
    }
    notCompiled(api);
}

rhi::DeviceHandle createDevice(rhi::Api api, [[maybe_unused]] const rhi::DeviceDesc& desc) {
    switch (api) {
    case rhi::Api::Vulkan:
#if LUMINA_HAS_VULKAN
        return vulkan::createDevice(desc);
#else
        break;
#endif
    case rhi::Api::D3D12:
#if LUMINA_HAS_D3D12
        return d3d12::createDevice(desc);
#else
        break;
#endif
    }
    notCompiled(api);
}

rhi::Api parseApi(std::string_view name) {
    if (name == "vulkan") {
        return rhi::Api::Vulkan;
    }
    if (name == "d3d12") {
        return rhi::Api::D3D12;
    }
    throw rhi::Error("unknown API '" + std::string(name) + "' (expected vulkan or d3d12)");
}

} // namespace lumina::app
