#pragma once
// The Vulkan backend's entry points; app/backends.cpp picks them at run time.
#include "rhi/device.h"

#include <vector>

namespace lumina::vulkan {

// Every Vulkan physical device, in the order createDevice's adapterIndex refers to.
std::vector<rhi::AdapterInfo> listAdapters();
rhi::DeviceHandle createDevice(const rhi::DeviceDesc& desc);

} // namespace lumina::vulkan
