#pragma once
#include <cstdint>
#include <string_view>

namespace lumina::rhi {

// The one state a whole resource is in between commands. Backends map each to their own
// layouts, access masks and pipeline stages (Vulkan) or D3D12_RESOURCE_STATES.
enum class ResourceState : uint8_t {
    Undefined,       // contents may be discarded
    Common,          // host-visible buffers, freshly created resources
    ConstantBuffer,
    IndexBuffer,
    IndirectArgument,
    ShaderResource,  // read by any shader stage (t registers)
    UnorderedAccess, // read-write by any shader stage (u registers)
    RenderTarget,
    DepthWrite,
    DepthRead,
    CopySource,
    CopyDest,
    Present,
};

std::string_view resourceStateName(ResourceState state);

} // namespace lumina::rhi
