#include "rhi_vulkan/vk_shader.h"

#include "rhi/error.h"
#include "rhi_vulkan/vk_check.h"
#include "rhi_vulkan/vk_context.h"
#include "rhi_vulkan/vk_struct.h"

#include <cstring>
#include <string>
#include <vector>

namespace lumina::vulkan {

namespace {
constexpr uint32_t kSpirvMagic = 0x07230203;
}

Shader::Shader(std::shared_ptr<Context> context, const rhi::ShaderDesc& desc, std::span<const uint8_t> spirv)
    : context_(std::move(context)), desc_(desc) {
    uint32_t magic = 0;
    if (spirv.size() >= sizeof(magic)) {
        std::memcpy(&magic, spirv.data(), sizeof(magic));
    }
    if (spirv.size() % 4 != 0 || magic != kSpirvMagic) {
        throw rhi::Error("createShader '" + desc_.debugName + "': not SPIR-V (" +
                         std::to_string(spirv.size()) + " bytes, magic " + std::to_string(magic) + ")");
    }
    // Copied into words: the caller's bytes need not be 4-byte aligned.
    std::vector<uint32_t> words(spirv.size() / 4);
    std::memcpy(words.data(), spirv.data(), spirv.size());
    auto info = vkStruct<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    info.codeSize = spirv.size();
    info.pCode = words.data();
    check(vkCreateShaderModule(context_->device(), &info, nullptr, &module_), "vkCreateShaderModule",
          desc_.debugName);
    context_->setName(VK_OBJECT_TYPE_SHADER_MODULE, module_, desc_.debugName);
}

Shader::~Shader() {
    vkDestroyShaderModule(context_->device(), module_, nullptr);
}

VkShaderStageFlagBits Shader::stage() const {
    switch (desc_.stage) {
    case rhi::ShaderStage::Compute:
        return VK_SHADER_STAGE_COMPUTE_BIT;
    case rhi::ShaderStage::Vertex:
        return VK_SHADER_STAGE_VERTEX_BIT;
    case rhi::ShaderStage::Pixel:
        return VK_SHADER_STAGE_FRAGMENT_BIT;
    }
    return VK_SHADER_STAGE_COMPUTE_BIT;
}

} // namespace lumina::vulkan
