#include "rhi_d3d12/d3d12_state.h"

#include "rhi/error.h"

namespace lumina::d3d12 {

D3D12_RESOURCE_STATES toD3D12State(rhi::ResourceState state, D3D12_COMMAND_LIST_TYPE listType) {
    switch (state) {
    case rhi::ResourceState::Undefined:
    case rhi::ResourceState::Common:
        return D3D12_RESOURCE_STATE_COMMON;
    case rhi::ResourceState::ConstantBuffer:
        return D3D12_RESOURCE_STATE_VERTEX_AND_CONSTANT_BUFFER;
    case rhi::ResourceState::IndexBuffer:
        return D3D12_RESOURCE_STATE_INDEX_BUFFER;
    case rhi::ResourceState::IndirectArgument:
        return D3D12_RESOURCE_STATE_INDIRECT_ARGUMENT;
    case rhi::ResourceState::ShaderResource:
        // Compute lists may not name pixel-shader states.
        return listType == D3D12_COMMAND_LIST_TYPE_DIRECT ? D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE |
                                                                D3D12_RESOURCE_STATE_PIXEL_SHADER_RESOURCE
                                                          : D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE;
    case rhi::ResourceState::UnorderedAccess:
        return D3D12_RESOURCE_STATE_UNORDERED_ACCESS;
    case rhi::ResourceState::RenderTarget:
        return D3D12_RESOURCE_STATE_RENDER_TARGET;
    case rhi::ResourceState::DepthWrite:
        return D3D12_RESOURCE_STATE_DEPTH_WRITE;
    case rhi::ResourceState::DepthRead:
        return D3D12_RESOURCE_STATE_DEPTH_READ;
    case rhi::ResourceState::CopySource:
        return D3D12_RESOURCE_STATE_COPY_SOURCE;
    case rhi::ResourceState::CopyDest:
        return D3D12_RESOURCE_STATE_COPY_DEST;
    case rhi::ResourceState::Present:
        return D3D12_RESOURCE_STATE_PRESENT;
    }
    return D3D12_RESOURCE_STATE_COMMON;
}

NativeResource& nativeResource(rhi::IResource& resource) {
    if (auto* native = dynamic_cast<NativeResource*>(&resource)) {
        return *native;
    }
    throw rhi::Error("resource '" + resource.debugName() + "' does not belong to a D3D12 device");
}

} // namespace lumina::d3d12
