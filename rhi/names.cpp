// Printable names of the RHI's enums, for logs and error messages.
#include "rhi/device.h"
#include "rhi/resource_state.h"

namespace lumina::rhi {

std::string_view resourceStateName(ResourceState state) {
    switch (state) {
    case ResourceState::Undefined: return "Undefined";
    case ResourceState::Common: return "Common";
    case ResourceState::ConstantBuffer: return "ConstantBuffer";
    case ResourceState::IndexBuffer: return "IndexBuffer";
    case ResourceState::IndirectArgument: return "IndirectArgument";
    case ResourceState::ShaderResource: return "ShaderResource";
    case ResourceState::UnorderedAccess: return "UnorderedAccess";
    case ResourceState::RenderTarget: return "RenderTarget";
    case ResourceState::DepthWrite: return "DepthWrite";
    case ResourceState::DepthRead: return "DepthRead";
    case ResourceState::CopySource: return "CopySource";
    case ResourceState::CopyDest: return "CopyDest";
    case ResourceState::Present: return "Present";
    }
    return "?";
}

std::string_view apiName(Api api) { return api == Api::Vulkan ? "vulkan" : "d3d12"; }

std::string_view adapterTypeName(AdapterType type) {
    switch (type) {
    case AdapterType::Discrete: return "discrete";
    case AdapterType::Integrated: return "integrated";
    case AdapterType::Virtual: return "virtual";
    case AdapterType::Cpu: return "cpu";
    case AdapterType::Other: return "other";
    }
    return "?";
}

} // namespace lumina::rhi
