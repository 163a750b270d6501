#pragma once
// rhi::ResourceState to D3D12_RESOURCE_STATES, and the native side of resource-state tracking.
// The shared rhi::StateTracker decides which barriers a command needs; each resource also
// remembers its actual D3D12 state, because one rhi state maps to different D3D12 states on
// direct and compute command lists (pixel-shader reads exist on direct lists only).
#include "rhi/resource.h"
#include "rhi_d3d12/d3d12_headers.h"

#include <memory>

namespace lumina::d3d12 {

D3D12_RESOURCE_STATES toD3D12State(rhi::ResourceState state, D3D12_COMMAND_LIST_TYPE listType);

// The native half of every D3D12 buffer and texture; reached from an rhi::IResource with
// nativeResource(). Command lists hold it by shared_ptr until their next begin().
class NativeResource : public std::enable_shared_from_this<NativeResource> {
public:
    virtual ~NativeResource() = default;
    ID3D12Resource* native() const { return resource_.Get(); }
    const ComPtr<ID3D12Resource>& nativeHandle() const { return resource_; }

    // The D3D12 state after every command list recorded so far (IResource::trackedState's twin).
    D3D12_RESOURCE_STATES currentState = D3D12_RESOURCE_STATE_COMMON;
    // Upload-heap resources stay in GENERIC_READ and readback-heap ones in COPY_DEST for life:
    // they are never transitioned.
    bool fixedState = false;
    // Buffers decay to COMMON when the ExecuteCommandLists that used them completes, and so
    // does every resource used on the copy queue; command lists return such resources to
    // COMMON at the end of their recording, so that every list starts from the state the
    // hardware is really in.
    bool isBuffer = false;

protected:
    ComPtr<ID3D12Resource> resource_;
};

// Throws rhi::Error when the resource belongs to another backend.
NativeResource& nativeResource(rhi::IResource& resource);

} // namespace lumina::d3d12
