#pragma once
// The VkInstance: layers, extensions, and the debug messenger that forwards validation
// messages to the application's callback.
#include "rhi/device.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

// Forwards validation warnings and errors to the DeviceDesc's callback and counts them.
// May be called from any thread the driver or layer reports on.
class MessageSink {
public:
    using Callback = std::function<void(rhi::MessageSeverity, std::string_view)>;
    explicit MessageSink(Callback callback) : callback_(std::move(callback)) {}

    void report(rhi::MessageSeverity severity, std::string_view message);
    uint64_t count() const { return count_.load(); }

private:
    Callback callback_;
    std::atomic<uint64_t> count_{0};
};

struct InstanceOptions {
    bool validation = false;
    bool synchronizationValidation = false;
    bool gpuBasedValidation = false;
    bool presentation = false; // VK_KHR_surface and this platform's surface extension
};

class Instance {
public:
    // `sink` receives validation messages (it must outlive the instance); null: none.
    Instance(const InstanceOptions& options, MessageSink* sink);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    VkInstance handle() const { return instance_; }
    std::vector<VkPhysicalDevice> physicalDevices() const;

    // VK_EXT_debug_utils entry points, null when the extension is not available.
    PFN_vkSetDebugUtilsObjectNameEXT setObjectName = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT cmdBeginLabel = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT cmdEndLabel = nullptr;

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
};

// Name, driver, API version, ids, type and device-local memory of one physical device.
rhi::AdapterInfo describeAdapter(VkPhysicalDevice physicalDevice, uint32_t index);

} // namespace lumina::vulkan
