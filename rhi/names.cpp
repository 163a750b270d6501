// Printable names of the RHI's enums, for logs and error messages.
#include "rhi/binding.h"
#include "rhi/command_list.h"
#include "rhi/device.h"
#include "rhi/resource.h"
#include "rhi/resource_state.h"

namespace lumina::rhi {

std::string_view resourceStateName(ResourceState state) {
    switch (state) {
    case ResourceState::Undefined:
        return "Undefined";
    case ResourceState::Common:
        return "Common";
    case ResourceState::ConstantBuffer:
        return "ConstantBuffer";
    case ResourceState::IndexBuffer:
        return "IndexBuffer";
    case ResourceState::IndirectArgument:
        return "IndirectArgument";
    case ResourceState::ShaderResource:
        return "ShaderResource";
    case ResourceState::UnorderedAccess:
        return "UnorderedAccess";
    case ResourceState::RenderTarget:
        return "RenderTarget";
    case ResourceState::DepthWrite:
        return "DepthWrite";
    case ResourceState::DepthRead:
        return "DepthRead";
    case ResourceState::CopySource:
        return "CopySource";
    case ResourceState::CopyDest:
        return "CopyDest";
    case ResourceState::Present:
        return "Present";
    }
    return "?";
}

std::string_view apiName(Api api) {
    return api == Api::Vulkan ? "vulkan" : "d3d12";
}

std::string_view adapterTypeName(AdapterType type) {
    switch (type) {
    case AdapterType::Discrete:
        return "discrete";
    case AdapterType::Integrated:
        return "integrated";
    case AdapterType::Virtual:
        return "virtual";
    case AdapterType::Cpu:
        return "cpu";
    case AdapterType::Other:
        return "other";
    }
    return "?";
}

const char* memoryTypeName(MemoryType memory) {
    switch (memory) {
    case MemoryType::GpuOnly:
        return "GpuOnly";
    case MemoryType::Upload:
        return "Upload";
    case MemoryType::Readback:
        return "Readback";
    }
    return "?";
}

const char* queueTypeName(QueueType type) {
    switch (type) {
    case QueueType::Graphics:
        return "graphics";
    case QueueType::Compute:
        return "compute";
    case QueueType::Copy:
        return "copy";
    }
    return "?";
}

const char* textureDimensionName(TextureDimension dimension) {
    switch (dimension) {
    case TextureDimension::Texture2D:
        return "Texture2D";
    case TextureDimension::Texture2DArray:
        return "Texture2DArray";
    case TextureDimension::Texture3D:
        return "Texture3D";
    case TextureDimension::TextureCube:
        return "TextureCube";
    case TextureDimension::TextureCubeArray:
        return "TextureCubeArray";
    }
    return "?";
}

char registerClass(BindingType type) {
    switch (type) {
    case BindingType::ConstantBuffer:
        return 'b';
    case BindingType::TextureSRV:
    case BindingType::BufferSRV:
    case BindingType::RawBufferSRV:
        return 't';
    case BindingType::TextureUAV:
    case BindingType::BufferUAV:
    case BindingType::RawBufferUAV:
        return 'u';
    case BindingType::Sampler:
        return 's';
    }
    return '?';
}

const char* bindingTypeName(BindingType type) {
    switch (type) {
    case BindingType::ConstantBuffer:
        return "constant buffer";
    case BindingType::TextureSRV:
        return "sampled texture (SRV)";
    case BindingType::BufferSRV:
        return "structured buffer (SRV)";
    case BindingType::RawBufferSRV:
        return "raw buffer (SRV)";
    case BindingType::TextureUAV:
        return "storage texture (UAV)";
    case BindingType::BufferUAV:
        return "RW structured buffer (UAV)";
    case BindingType::RawBufferUAV:
        return "RW raw buffer (UAV)";
    case BindingType::Sampler:
        return "sampler";
    }
    return "?";
}

} // namespace lumina::rhi
