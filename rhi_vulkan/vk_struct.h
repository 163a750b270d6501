#pragma once
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

// A zeroed Vulkan info struct with its sType set. (`VkFooInfo info{VK_STRUCTURE_TYPE_...}`
// would trip -Wmissing-field-initializers, which the project builds with as an error.)
template <typename T>
T vkStruct(VkStructureType type) {
    T value{};
    value.sType = type;
    return value;
}

} // namespace lumina::vulkan
