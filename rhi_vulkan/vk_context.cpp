#include "rhi_vulkan/vk_context.h"

#include "rhi/error.h"
#include "rhi/out_of_memory_error.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_struct.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace lumina::vulkan {

namespace {

constexpr uint32_t kNoMemoryType = ~0u;

uint32_t findMemoryType(const VkPhysicalDeviceMemoryProperties& properties, uint32_t allowedTypes,
                        VkMemoryPropertyFlags flags) {
    for (uint32_t type = 0; type < properties.memoryTypeCount; ++type) {
        if ((allowedTypes & (1u << type)) && (properties.memoryTypes[type].propertyFlags & flags) == flags) {
            return type;
        }
    }
    return kNoMemoryType;
}

} // namespace

Context::Context(const rhi::DeviceDesc& desc)
    : presentation_(desc.presentation), messages_(desc.messageCallback),
      instance_({.validation = desc.validation,
                 .synchronizationValidation = desc.synchronizationValidation,
                 .gpuBasedValidation = desc.gpuBasedValidation,
                 .presentation = desc.presentation},
                &messages_) {
    const auto physicalDevices = instance_.physicalDevices();
    if (desc.adapterIndex >= physicalDevices.size()) {
        throw rhi::Error("Vulkan adapter " + std::to_string(desc.adapterIndex) +
                         " does not exist: " + std::to_string(physicalDevices.size()) + " found" +
                         (physicalDevices.empty() ? " (install mesa-vulkan-drivers for lavapipe)" : ""));
    }
    physicalDevice_ = physicalDevices[desc.adapterIndex];
    adapter_ = describeAdapter(physicalDevice_, desc.adapterIndex);

    auto properties11 =
        vkStruct<VkPhysicalDeviceVulkan11Properties>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES);
    auto properties = vkStruct<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
    properties.pNext = &properties11;
    vkGetPhysicalDeviceProperties2(physicalDevice_, &properties);
    properties_ = properties.properties;
    subgroupSize_ = properties11.subgroupSize;
    vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memoryProperties_);
    VkDeviceSize largestHeap = 0;
    for (uint32_t i = 0; i < memoryProperties_.memoryHeapCount; ++i) {
        largestHeap = std::max(largestHeap, memoryProperties_.memoryHeaps[i].size);
    }
    maxAllocationBytes_ = std::min<uint64_t>(properties11.maxMemoryAllocationSize, largestHeap);
    if (properties_.apiVersion < VK_API_VERSION_1_3) {
        throw rhi::Error("Vulkan adapter '" + adapter_.name + "' supports Vulkan " + adapter_.apiVersion +
                         "; Lumina needs 1.3 (dynamic rendering, synchronization2)");
    }
    createDevice();
}

Context::~Context() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        vkDestroyDevice(device_, nullptr);
    }
}

void Context::createDevice() {
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, families.data());

    // Graphics: the first family that does graphics and compute (the spec guarantees one).
    // Compute: a compute-only family if there is one (async compute on real GPUs), else a
    // second queue of the graphics family, else the graphics queue itself.
    constexpr uint32_t kNone = ~0u;
    uint32_t graphicsFamily = kNone;
    uint32_t computeFamily = kNone;
    for (uint32_t family = 0; family < familyCount; ++family) {
        const VkQueueFlags flags = families[family].queueFlags;
        const bool graphics = flags & VK_QUEUE_GRAPHICS_BIT;
        const bool compute = flags & VK_QUEUE_COMPUTE_BIT;
        if (graphics && compute && graphicsFamily == kNone) {
            graphicsFamily = family;
        }
        if (compute && !graphics && computeFamily == kNone) {
            computeFamily = family;
        }
    }
    if (graphicsFamily == kNone) {
        throw rhi::Error("Vulkan adapter '" + adapter_.name +
                         "' has no queue family with graphics and compute");
    }
    uint32_t computeIndex = 0;
    if (computeFamily == kNone) {
        computeFamily = graphicsFamily;
        computeIndex = families[graphicsFamily].queueCount > 1 ? 1 : 0;
    }

    const float priorities[] = {1.0f, 1.0f};
    std::vector<VkDeviceQueueCreateInfo> queueInfos;
    auto graphicsInfo = vkStruct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    graphicsInfo.queueFamilyIndex = graphicsFamily;
    graphicsInfo.queueCount = computeFamily == graphicsFamily ? computeIndex + 1 : 1;
    graphicsInfo.pQueuePriorities = priorities;
    queueInfos.push_back(graphicsInfo);
    if (computeFamily != graphicsFamily) {
        VkDeviceQueueCreateInfo computeInfo = graphicsInfo;
        computeInfo.queueFamilyIndex = computeFamily;
        computeInfo.queueCount = 1;
        queueInfos.push_back(computeInfo);
    }

    // Features: the three Lumina cannot work without, then the optional ones it uses
    // wherever the device has them.
    auto supported13 =
        vkStruct<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    auto supported12 =
        vkStruct<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
    auto supported11 =
        vkStruct<VkPhysicalDeviceVulkan11Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
    auto supported = vkStruct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
    supported.pNext = &supported11;
    supported11.pNext = &supported12;
    supported12.pNext = &supported13;
    vkGetPhysicalDeviceFeatures2(physicalDevice_, &supported);

    const auto require = [&](VkBool32 present, const char* name) {
        if (!present) {
            throw rhi::Error("Vulkan adapter '" + adapter_.name + "' lacks the required feature " + name);
        }
    };
    require(supported12.timelineSemaphore, "timelineSemaphore");
    require(supported13.synchronization2, "synchronization2");
    require(supported13.dynamicRendering, "dynamicRendering");
    // Filtering 32-bit float textures is optional in Vulkan (D3D12 requires it); the screen probes'
    // irradiance atlas is one, sampled bilinearly (a half-float atlas rounded a furnace's light by up to
    // 0.04 %, docs/screen_probes.md#ranges).
    VkFormatProperties rgba32f{};
    vkGetPhysicalDeviceFormatProperties(physicalDevice_, VK_FORMAT_R32G32B32A32_SFLOAT, &rgba32f);
    require((rgba32f.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0,
            "linear filtering of VK_FORMAT_R32G32B32A32_SFLOAT");

    auto enabled13 =
        vkStruct<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    auto enabled12 =
        vkStruct<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
    auto enabled11 =
        vkStruct<VkPhysicalDeviceVulkan11Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
    auto enabled = vkStruct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
    enabled.pNext = &enabled11;
    enabled11.pNext = &enabled12;
    enabled12.pNext = &enabled13;

#define LUMINA_ENABLE_IF_SUPPORTED(in, out, feature) (out).feature = (in).feature
    LUMINA_ENABLE_IF_SUPPORTED(supported13, enabled13, synchronization2);
    LUMINA_ENABLE_IF_SUPPORTED(supported13, enabled13, dynamicRendering);
    LUMINA_ENABLE_IF_SUPPORTED(supported13, enabled13, maintenance4);
    LUMINA_ENABLE_IF_SUPPORTED(supported12, enabled12, timelineSemaphore);
    LUMINA_ENABLE_IF_SUPPORTED(supported12, enabled12, hostQueryReset);
    LUMINA_ENABLE_IF_SUPPORTED(supported12, enabled12, scalarBlockLayout);
    LUMINA_ENABLE_IF_SUPPORTED(supported12, enabled12, uniformBufferStandardLayout);
    LUMINA_ENABLE_IF_SUPPORTED(supported11, enabled11, shaderDrawParameters);
    // Kernels write storage buffers and images from every stage, gather with offsets and use
    // the extended storage formats (rg16f, r16f, ...).
    // geometryShader: the GBuffer's visibility pixel shader reads SV_PrimitiveID (SPIR-V's
    // PrimitiveId in a fragment shader needs the Geometry capability).
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, geometryShader);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, depthClamp);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, fillModeNonSolid);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, samplerAnisotropy);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, imageCubeArray);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, independentBlend);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, fragmentStoresAndAtomics);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, vertexPipelineStoresAndAtomics);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, shaderImageGatherExtended);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, shaderStorageImageExtendedFormats);
    LUMINA_ENABLE_IF_SUPPORTED(supported.features, enabled.features, shaderStorageImageWriteWithoutFormat);
#undef LUMINA_ENABLE_IF_SUPPORTED

    features_.depthClamp = enabled.features.depthClamp;
    features_.fillModeNonSolid = enabled.features.fillModeNonSolid;
    features_.samplerAnisotropy = enabled.features.samplerAnisotropy;
    features_.imageCubeArray = enabled.features.imageCubeArray;
    features_.independentBlend = enabled.features.independentBlend;
    features_.hostQueryReset = enabled12.hostQueryReset;

    std::vector<const char*> extensions;
    if (presentation_) {
        uint32_t count = 0;
        vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &count, nullptr);
        std::vector<VkExtensionProperties> available(count);
        vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &count, available.data());
        features_.swapchain =
            std::any_of(available.begin(), available.end(), [](const VkExtensionProperties& e) {
                return std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0;
            });
        if (!features_.swapchain) {
            throw rhi::Error("Vulkan adapter '" + adapter_.name + "' cannot present: no " +
                             VK_KHR_SWAPCHAIN_EXTENSION_NAME);
        }
        extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }

    auto info = vkStruct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    info.pNext = &enabled;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    info.queueCreateInfoCount = static_cast<uint32_t>(queueInfos.size());
    info.pQueueCreateInfos = queueInfos.data();
    check(vkCreateDevice(physicalDevice_, &info, nullptr, &device_), "vkCreateDevice", adapter_.name);

    const auto makeQueue = [&](uint32_t family, uint32_t index) {
        auto queue = std::make_shared<HardwareQueue>();
        vkGetDeviceQueue(device_, family, index, &queue->queue);
        queue->family = family;
        queue->index = index;
        queue->supportsGraphics = families[family].queueFlags & VK_QUEUE_GRAPHICS_BIT;
        queue->timestampValidBits = families[family].timestampValidBits;
        return queue;
    };
    graphicsQueue_ = makeQueue(graphicsFamily, 0);
    const bool sharesGraphics = computeFamily == graphicsFamily && computeIndex == 0;
    computeQueue_ = sharesGraphics ? graphicsQueue_ : makeQueue(computeFamily, computeIndex);
    queueFamilies_.push_back(graphicsFamily);
    if (computeFamily != graphicsFamily) {
        queueFamilies_.push_back(computeFamily);
    }
    setName(VK_OBJECT_TYPE_QUEUE, graphicsQueue_->queue, "graphics queue");
    if (!sharesGraphics) {
        setName(VK_OBJECT_TYPE_QUEUE, computeQueue_->queue, "compute queue");
    }
}

void Context::checkAllocationSize(uint64_t bytes, std::string_view debugName) const {
    if (bytes > maxAllocationBytes_) {
        constexpr uint64_t kMiB = uint64_t(1) << 20;
        throw rhi::OutOfMemoryError("out of GPU memory: '" + std::string(debugName) + "' needs " +
                                    std::to_string((bytes + kMiB - 1) / kMiB) + " MiB, and " + adapter_.name +
                                    " allocates at most " + std::to_string(maxAllocationBytes_ / kMiB) +
                                    " MiB at once");
    }
}

VkDeviceMemory Context::allocateMemory(const VkMemoryRequirements& requirements, rhi::MemoryType memory,
                                       std::string_view debugName) {
    // Preferred flags first, then the minimum that still works.
    VkMemoryPropertyFlags preferred = 0;
    VkMemoryPropertyFlags minimum = 0;
    switch (memory) {
    case rhi::MemoryType::GpuOnly:
        preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        break;
    case rhi::MemoryType::Upload:
        preferred = minimum = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        break;
    case rhi::MemoryType::Readback:
        // Cached: the CPU reads it back, and uncached reads are very slow.
        minimum = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        preferred = minimum | VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
        break;
    }
    uint32_t type = findMemoryType(memoryProperties_, requirements.memoryTypeBits, preferred);
    if (type == kNoMemoryType) {
        type = findMemoryType(memoryProperties_, requirements.memoryTypeBits, minimum);
    }
    const std::string context = std::to_string(requirements.size) + " bytes of " +
                                rhi::memoryTypeName(memory) + " memory for '" + std::string(debugName) + "'";
    if (type == kNoMemoryType) {
        throw rhi::Error("no Vulkan memory type fits " + context);
    }
    checkAllocationSize(requirements.size, debugName);
    auto info = vkStruct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = type;
    VkDeviceMemory result = VK_NULL_HANDLE;
    check(vkAllocateMemory(device_, &info, nullptr, &result), "vkAllocateMemory", context);
    allocatedBytes_ += requirements.size;
    return result;
}

void Context::freeMemory(VkDeviceMemory memory, VkDeviceSize size) {
    if (memory) {
        vkFreeMemory(device_, memory, nullptr);
        allocatedBytes_ -= size;
    }
}

void Context::setName(VkObjectType type, uint64_t handle, std::string_view name) const {
    if (!instance_.setObjectName || name.empty() || handle == 0) {
        return;
    }
    const std::string terminated(name);
    auto info = vkStruct<VkDebugUtilsObjectNameInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT);
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = terminated.c_str();
    instance_.setObjectName(device_, &info);
}

void Context::beginLabel(VkCommandBuffer commandBuffer, std::string_view name) const {
    if (!instance_.cmdBeginLabel) {
        return;
    }
    const std::string terminated(name);
    auto label = vkStruct<VkDebugUtilsLabelEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT);
    label.pLabelName = terminated.c_str();
    instance_.cmdBeginLabel(commandBuffer, &label);
}

void Context::endLabel(VkCommandBuffer commandBuffer) const {
    if (instance_.cmdEndLabel) {
        instance_.cmdEndLabel(commandBuffer);
    }
}

} // namespace lumina::vulkan
