#include "rhi_vulkan/vk_backend.h"

#include "rhi_vulkan/vk_device.h"
#include "rhi_vulkan/vk_instance.h"

namespace lumina::vulkan {

std::vector<rhi::AdapterInfo> listAdapters() {
    // A plain instance: no layers, no messenger, nothing to report.
    const Instance instance({}, nullptr);
    std::vector<rhi::AdapterInfo> adapters;
    const auto physicalDevices = instance.physicalDevices();
    for (uint32_t index = 0; index < physicalDevices.size(); ++index) {
        adapters.push_back(describeAdapter(physicalDevices[index], index));
    }
    return adapters;
}

rhi::DeviceHandle createDevice(const rhi::DeviceDesc& desc) {
    return std::make_unique<Device>(desc);
}

} // namespace lumina::vulkan
