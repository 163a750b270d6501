#pragma once
// What every Vulkan object of one device shares: the instance, the VkDevice, its queues,
// enabled features, memory allocation and debug naming. Objects hold a shared_ptr to it,
// so the VkDevice outlives the last buffer or command list the application keeps.
#include "rhi/device.h"
#include "rhi_vulkan/vk_instance.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string_view>
#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

// One VkQueue. Several rhi queues may share it (lavapipe has one queue in all): submits
// to it are serialised by `submitMutex`.
struct HardwareQueue {
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t family = 0;
    uint32_t index = 0;
    bool supportsGraphics = false;
    uint32_t timestampValidBits = 0;
    std::mutex submitMutex;
};

// Optional features, enabled only where the physical device reports them.
struct EnabledFeatures {
    bool depthClamp = false;
    bool fillModeNonSolid = false;
    bool samplerAnisotropy = false;
    bool imageCubeArray = false;
    bool independentBlend = false;
    bool hostQueryReset = false;
    bool swapchain = false; // VK_KHR_swapchain, with DeviceDesc::presentation
};

class Context {
public:
    explicit Context(const rhi::DeviceDesc& desc);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_.handle(); }
    VkDevice device() const { return device_; }
    VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    const VkPhysicalDeviceLimits& limits() const { return properties_.limits; }
    uint32_t subgroupSize() const { return subgroupSize_; }
    const EnabledFeatures& features() const { return features_; }
    const rhi::AdapterInfo& adapter() const { return adapter_; }
    // On CPU implementations (lavapipe) a timestamp is not taken where it stands in the command
    // stream but when the stream is next flushed; a dispatch runs at once. Seen: a lone 60 ms
    // dispatch between two timestamps read 0.1 ms. A pipeline barrier flushes, so command lists
    // put one right after every timestamp there; real GPUs honour the timestamp's stage.
    bool timestampsNeedBarrier() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }

    const std::shared_ptr<HardwareQueue>& graphicsQueue() const { return graphicsQueue_; }
    const std::shared_ptr<HardwareQueue>& computeQueue() const { return computeQueue_; }
    // The distinct queue families in use: resources are created VK_SHARING_MODE_CONCURRENT
    // across them when there is more than one, so no ownership transfers are needed.
    const std::vector<uint32_t>& queueFamilies() const { return queueFamilies_; }

    // Throws rhi::OutOfMemoryError naming `debugName` when `bytes` is more than the device
    // allocates at once (maxMemoryAllocationSize, or its largest heap): checked before a
    // resource is created, because creating one past the limits is undefined in Vulkan.
    void checkAllocationSize(uint64_t bytes, std::string_view debugName) const;
    // One allocation per resource; counted in allocatedBytes().
    VkDeviceMemory allocateMemory(const VkMemoryRequirements& requirements, rhi::MemoryType memory,
                                  std::string_view debugName);
    void freeMemory(VkDeviceMemory memory, VkDeviceSize size);
    uint64_t allocatedBytes() const { return allocatedBytes_.load(); }

    // No-ops without VK_EXT_debug_utils.
    void setName(VkObjectType type, uint64_t handle, std::string_view name) const;
    template <typename Handle>
    void setName(VkObjectType type, Handle handle, std::string_view name) const {
        setName(type, reinterpret_cast<uint64_t>(handle), name);
    }
    void beginLabel(VkCommandBuffer commandBuffer, std::string_view name) const;
    void endLabel(VkCommandBuffer commandBuffer) const;
    bool hasLabels() const { return instance_.cmdBeginLabel != nullptr; }

    MessageSink& messages() { return messages_; }
    uint64_t messageCount() const { return messages_.count(); }

private:
    void createDevice();

    bool presentation_ = false;
    // Declared first: the sink must outlive the instance's messenger.
    MessageSink messages_;
    Instance instance_;
    VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memoryProperties_{};
    uint32_t subgroupSize_ = 0;
    uint64_t maxAllocationBytes_ = 0; // maxMemoryAllocationSize, at most the largest heap
    rhi::AdapterInfo adapter_;
    EnabledFeatures features_;
    VkDevice device_ = VK_NULL_HANDLE;
    std::shared_ptr<HardwareQueue> graphicsQueue_;
    std::shared_ptr<HardwareQueue> computeQueue_;
    std::vector<uint32_t> queueFamilies_;
    std::atomic<uint64_t> allocatedBytes_{0};
};

} // namespace lumina::vulkan
