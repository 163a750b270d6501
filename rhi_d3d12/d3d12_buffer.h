#pragma once
// Buffers: committed resources in the default, upload or readback heap. Upload and readback
// buffers are mapped for life. Views are created on first use, in the CPU-only staging heap,
// and cached for the buffer's lifetime.
#include "rhi/binding.h"
#include "rhi/resource.h"
#include "rhi_d3d12/d3d12_context.h"
#include "rhi_d3d12/d3d12_state.h"

#include <map>
#include <mutex>
#include <tuple>

namespace lumina::d3d12 {

// Constant-buffer views must start and end on 256 bytes, so every buffer's allocation is
// rounded up to it.
constexpr uint64_t kConstantBufferAlignment = D3D12_CONSTANT_BUFFER_DATA_PLACEMENT_ALIGNMENT;

class Buffer final : public rhi::IBuffer, public NativeResource {
public:
    Buffer(ContextHandle context, const rhi::BufferDesc& desc);
    ~Buffer() override;

    const rhi::BufferDesc& desc() const override { return desc_; }
    void* map() override;

    D3D12_GPU_VIRTUAL_ADDRESS gpuAddress() const { return resource_->GetGPUVirtualAddress(); }
    // A CBV, SRV or UAV of `range` for a binding of `type`; throws rhi::Error naming the buffer
    // when its usage, memory or alignment does not allow it.
    D3D12_CPU_DESCRIPTOR_HANDLE view(rhi::BindingType type, rhi::BufferRange range);
    // A raw UAV of the whole buffer (rounded down to 4 bytes), for fillBuffer.
    D3D12_CPU_DESCRIPTOR_HANDLE wholeRawUav();

private:
    D3D12_CPU_DESCRIPTOR_HANDLE createView(rhi::BindingType type, uint64_t offset, uint64_t size);

    ContextHandle context_;
    rhi::BufferDesc desc_;
    uint64_t allocatedBytes_ = 0;
    void* mapped_ = nullptr;
    std::mutex viewMutex_;
    std::map<std::tuple<rhi::BindingType, uint64_t, uint64_t>, D3D12_CPU_DESCRIPTOR_HANDLE> views_;
};

// Throws rhi::Error when the buffer belongs to another backend.
Buffer& toBuffer(rhi::IBuffer& buffer);

} // namespace lumina::d3d12
