#include "rhi_vulkan/vk_instance.h"
#include "rhi_vulkan/vk_swapchain_surface.h"

#include "rhi/error.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_struct.h"

#include <algorithm>
#include <cstring>
#include <string>

#if LUMINA_SANITIZE
#include <dlfcn.h>
#endif

namespace lumina::vulkan {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasLayer(const char* name) {
    uint32_t count = 0;
    check(vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties");
    std::vector<VkLayerProperties> layers(count);
    check(vkEnumerateInstanceLayerProperties(&count, layers.data()), "vkEnumerateInstanceLayerProperties");
    return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& layer) {
        return std::strcmp(layer.layerName, name) == 0;
    });
}

bool hasInstanceExtension(const char* name, const char* layer = nullptr) {
    uint32_t count = 0;
    check(vkEnumerateInstanceExtensionProperties(layer, &count, nullptr),
          "vkEnumerateInstanceExtensionProperties");
    std::vector<VkExtensionProperties> extensions(count);
    check(vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()),
          "vkEnumerateInstanceExtensionProperties");
    return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& extension) {
        return std::strcmp(extension.extensionName, name) == 0;
    });
}

VKAPI_ATTR VkBool32 VKAPI_CALL forwardMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    const auto level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT
                           ? rhi::MessageSeverity::Error
                           : rhi::MessageSeverity::Warning;
    std::string message = data->pMessage ? data->pMessage : "";
    // The layer's text usually names the VUID already; loader messages may not.
    if (data->pMessageIdName && message.find(data->pMessageIdName) == std::string::npos) {
        message = "[" + std::string(data->pMessageIdName) + "] " + message;
    }
    static_cast<MessageSink*>(user)->report(level, message);
    return VK_FALSE; // never abort the call that triggered the message
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(MessageSink* sink) {
    auto info =
        vkStruct<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = forwardMessage;
    info.pUserData = sink;
    return info;
}

std::string versionString(uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

rhi::AdapterType adapterType(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return rhi::AdapterType::Discrete;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return rhi::AdapterType::Integrated;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return rhi::AdapterType::Virtual;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return rhi::AdapterType::Cpu;
    default:
        return rhi::AdapterType::Other;
    }
}

} // namespace

void MessageSink::report(rhi::MessageSeverity severity, std::string_view message) {
    if (severity != rhi::MessageSeverity::Info) {
        ++count_;
    }
    if (callback_) {
        callback_(severity, message);
    }
}

#if LUMINA_SANITIZE
namespace {
// The sanitizer build only (.ci/sanitizers.sh): LeakSanitizer reports at exit, when the Vulkan
// loader has already unloaded the driver and the layers, so their leaks show as "<unknown
// module>", which no suppression can name. Loaded once more here and never unloaded, they keep
// their names for tests/sanitizers/lsan.supp. A library that is not installed is skipped.
void keepVulkanLibrariesLoaded() {
    for (const char* library : {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"}) {
        (void)dlopen(library, RTLD_NOW | RTLD_NODELETE);
    }
}
} // namespace
#endif

Instance::Instance(const InstanceOptions& options, MessageSink* sink) {
#if LUMINA_SANITIZE
    keepVulkanLibrariesLoaded();
#endif
    uint32_t loaderVersion = VK_API_VERSION_1_0;
    check(vkEnumerateInstanceVersion(&loaderVersion), "vkEnumerateInstanceVersion");
    if (loaderVersion < VK_API_VERSION_1_3) {
        throw rhi::Error("the Vulkan loader supports Vulkan " + versionString(loaderVersion) +
                         "; Lumina needs 1.3 (update libvulkan1)");
    }

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    const bool validation =
        options.validation || options.synchronizationValidation || options.gpuBasedValidation;
    if (validation) {
        if (!hasLayer(kValidationLayer)) {
            throw rhi::Error(
                "Vulkan validation was requested but VK_LAYER_KHRONOS_validation is not installed: "
                "install vulkan-validationlayers (Debian/Ubuntu) or the Vulkan SDK");
        }
        layers.push_back(kValidationLayer);
    }
    const bool debugUtils =
        hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
        (validation && hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, kValidationLayer));
    if (debugUtils) {
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }

    if (options.presentation) {
        for (const char* surface : presentationExtensions()) {
            if (!hasInstanceExtension(surface)) {
                throw rhi::Error(std::string("presenting to a window needs the Vulkan instance extension ") +
                                 surface + ", which the loader and drivers do not offer");
            }
            extensions.push_back(surface);
        }
    }

    std::vector<VkValidationFeatureEnableEXT> enabledChecks;
    if (options.synchronizationValidation) {
        enabledChecks.push_back(VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT);
    }
    if (options.gpuBasedValidation) {
        enabledChecks.push_back(VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_EXT);
    }
    if (!enabledChecks.empty()) {
        if (!hasInstanceExtension(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME, kValidationLayer)) {
            throw rhi::Error(
                "the installed Vulkan validation layer lacks VK_EXT_validation_features, needed for "
                "synchronization or GPU-assisted validation: update vulkan-validationlayers");
        }
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    }

    auto app = vkStruct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "Lumina";
    app.pEngineName = "Lumina";
    app.apiVersion = VK_API_VERSION_1_3;

    auto info = vkStruct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();

    // Chained so that messages about instance creation itself reach the sink too.
    VkDebugUtilsMessengerCreateInfoEXT messenger = messengerInfo(sink);
    auto features = vkStruct<VkValidationFeaturesEXT>(VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT);
    const void** next = &info.pNext;
    if (debugUtils && sink) {
        *next = &messenger;
        next = &messenger.pNext;
    }
    if (!enabledChecks.empty()) {
        features.enabledValidationFeatureCount = static_cast<uint32_t>(enabledChecks.size());
        features.pEnabledValidationFeatures = enabledChecks.data();
        *next = &features;
    }
    check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance");

    if (debugUtils) {
        setObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
            vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
        cmdBeginLabel = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(instance_, "vkCmdBeginDebugUtilsLabelEXT"));
        cmdEndLabel = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(instance_, "vkCmdEndDebugUtilsLabelEXT"));
        if (sink) {
            auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
            messenger.pNext = nullptr;
            check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
        }
    }
}

Instance::~Instance() {
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance_, messenger_, nullptr);
    }
    vkDestroyInstance(instance_, nullptr);
}

std::vector<VkPhysicalDevice> Instance::physicalDevices() const {
    uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()), "vkEnumeratePhysicalDevices");
    devices.resize(count);
    return devices;
}

rhi::AdapterInfo describeAdapter(VkPhysicalDevice physicalDevice, uint32_t index) {
    auto driver =
        vkStruct<VkPhysicalDeviceDriverProperties>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES);
    auto properties = vkStruct<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
    properties.pNext = &driver;
    vkGetPhysicalDeviceProperties2(physicalDevice, &properties);
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memory);

    rhi::AdapterInfo info;
    info.index = index;
    info.name = properties.properties.deviceName;
    info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
    info.apiVersion = versionString(properties.properties.apiVersion);
    info.vendorId = properties.properties.vendorID;
    info.deviceId = properties.properties.deviceID;
    info.type = adapterType(properties.properties.deviceType);
    for (uint32_t heap = 0; heap < memory.memoryHeapCount; ++heap) {
        if (memory.memoryHeaps[heap].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) {
            info.dedicatedMemoryBytes += memory.memoryHeaps[heap].size;
        }
    }
    return info;
}

} // namespace lumina::vulkan
