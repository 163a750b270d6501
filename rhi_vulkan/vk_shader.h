#pragma once
#include "rhi/pipeline.h"

#include <memory>
#include <span>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

class Context;

// A SPIR-V module and the entry point its pipelines use.
class Shader final : public rhi::IShader {
public:
    Shader(std::shared_ptr<Context> context, const rhi::ShaderDesc& desc, std::span<const uint8_t> spirv);
    ~Shader() override;
    Shader(const Shader&) = delete;
    Shader& operator=(const Shader&) = delete;

    const rhi::ShaderDesc& desc() const override { return desc_; }
    VkShaderModule handle() const { return module_; }
    VkShaderStageFlagBits stage() const;

private:
    std::shared_ptr<Context> context_;
    rhi::ShaderDesc desc_;
    VkShaderModule module_ = VK_NULL_HANDLE;
};

} // namespace lumina::vulkan
