#include "rhi_vulkan/vk_check.h"

#include "rhi/error.h"
#include "rhi/out_of_memory_error.h"

#include <string>

namespace lumina::vulkan {

std::string_view resultName(VkResult result) {
    switch (result) {
#define LUMINA_VK_RESULT(name)                                                                               \
    case name:                                                                                               \
        return #name;
        LUMINA_VK_RESULT(VK_SUCCESS)
        LUMINA_VK_RESULT(VK_NOT_READY)
        LUMINA_VK_RESULT(VK_TIMEOUT)
        LUMINA_VK_RESULT(VK_EVENT_SET)
        LUMINA_VK_RESULT(VK_EVENT_RESET)
        LUMINA_VK_RESULT(VK_INCOMPLETE)
        LUMINA_VK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        LUMINA_VK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        LUMINA_VK_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        LUMINA_VK_RESULT(VK_ERROR_DEVICE_LOST)
        LUMINA_VK_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        LUMINA_VK_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        LUMINA_VK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        LUMINA_VK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        LUMINA_VK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        LUMINA_VK_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        LUMINA_VK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        LUMINA_VK_RESULT(VK_ERROR_FRAGMENTED_POOL)
        LUMINA_VK_RESULT(VK_ERROR_UNKNOWN)
        LUMINA_VK_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        LUMINA_VK_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        LUMINA_VK_RESULT(VK_ERROR_FRAGMENTATION)
        LUMINA_VK_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        LUMINA_VK_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
        LUMINA_VK_RESULT(VK_ERROR_SURFACE_LOST_KHR)
        LUMINA_VK_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        LUMINA_VK_RESULT(VK_SUBOPTIMAL_KHR)
        LUMINA_VK_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
        LUMINA_VK_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
        LUMINA_VK_RESULT(VK_ERROR_INVALID_SHADER_NV)
#undef LUMINA_VK_RESULT
    default:
        break;
    }
    return "VK_RESULT_UNKNOWN";
}

void check(VkResult result, std::string_view call, std::string_view context) {
    if (result >= 0) {
        return;
    }
    std::string message = std::string(call) + " failed: " + std::string(resultName(result)) + " (" +
                          std::to_string(static_cast<int>(result)) + ")";
    if (!context.empty()) {
        message += " [" + std::string(context) + "]";
    }
    if (result == VK_ERROR_DEVICE_LOST) {
        throw rhi::DeviceLostError(message);
    }
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY) {
        throw rhi::OutOfMemoryError("out of GPU memory: " + message);
    }
    throw rhi::Error(message);
}

} // namespace lumina::vulkan
