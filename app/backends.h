#pragma once
// The backends compiled into this build, picked at run time by API name.
#include <string_view>
#include <vector>

#include "rhi/device.h"

namespace lumina::app {

std::vector<rhi::Api> compiledApis();
// Throws rhi::Error naming the API when it was not compiled in.
std::vector<rhi::AdapterInfo> listAdapters(rhi::Api api);
rhi::DeviceHandle createDevice(rhi::Api api, const rhi::DeviceDesc& desc);
// "vulkan" or "d3d12"; throws rhi::Error listing the valid names otherwise.
rhi::Api parseApi(std::string_view name);

} // namespace lumina::app
