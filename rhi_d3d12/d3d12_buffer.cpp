#include "rhi_d3d12/d3d12_buffer.h"

#include "rhi/validation.h"
#include "rhi_d3d12/d3d12_binding.h"
#include "rhi_d3d12/d3d12_check.h"

#include <string>

namespace lumina::d3d12 {

static_assert(rhi::kConstantBufferOffsetAlignment == kConstantBufferAlignment);

namespace {

uint64_t alignUp(uint64_t value, uint64_t alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

} // namespace

Buffer::Buffer(ContextHandle context, const rhi::BufferDesc& desc)
    : context_(std::move(context)), desc_(desc) {
    rhi::validateBufferDesc(desc);
    D3D12_RESOURCE_DESC resourceDesc{};
    resourceDesc.Dimension = D3D12_RESOURCE_DIMENSION_BUFFER;
    resourceDesc.Width = alignUp(desc.size, kConstantBufferAlignment);
    resourceDesc.Height = 1;
    resourceDesc.DepthOrArraySize = 1;
    resourceDesc.MipLevels = 1;
    resourceDesc.Format = DXGI_FORMAT_UNKNOWN;
    resourceDesc.SampleDesc.Count = 1;
    resourceDesc.Layout = D3D12_TEXTURE_LAYOUT_ROW_MAJOR;

    isBuffer = true;
    D3D12_HEAP_PROPERTIES heap{};
    heap.Type = D3D12_HEAP_TYPE_DEFAULT;
    switch (desc.memory) {
    case rhi::MemoryType::GpuOnly:
        // Every default-heap buffer may take UAVs: fillBuffer clears through one.
        resourceDesc.Flags = D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS;
        currentState = D3D12_RESOURCE_STATE_COMMON;
        break;
    case rhi::MemoryType::Upload:
        heap.Type = D3D12_HEAP_TYPE_UPLOAD;
        currentState = D3D12_RESOURCE_STATE_GENERIC_READ;
        fixedState = true;
        break;
    case rhi::MemoryType::Readback:
        // The readback heap's memory (write-back, CPU-cached) as a custom heap: resources in
        // the READBACK heap type stay in COPY_DEST for life, and then nothing could order two
        // GPU writes into one (legacy barriers have no copy-to-copy barrier). In a custom heap
        // the buffer transitions like any other.
        heap = customHeapProperties(context_->device(), D3D12_HEAP_TYPE_READBACK);
        currentState = D3D12_RESOURCE_STATE_COPY_DEST;
        break;
    }
    resource_ =
        context_->createCommittedResource(heap, resourceDesc, currentState, desc.debugName, allocatedBytes_);
    if (desc.memory != rhi::MemoryType::GpuOnly) {
        check(resource_->Map(0, nullptr, &mapped_), "ID3D12Resource::Map('" + desc.debugName + "')",
              *context_);
    }
}

Buffer::~Buffer() {
    for (const auto& [key, handle] : views_) {
        context_->stagingViews().free(handle);
    }
    if (mapped_) {
        resource_->Unmap(0, nullptr);
    }
    context_->releaseMemory(allocatedBytes_);
}

void* Buffer::map() {
    if (!mapped_) {
        throw rhi::Error("map('" + desc_.debugName +
                         "'): a GpuOnly buffer has no host pointer; use Upload or "
                         "Readback memory");
    }
    return mapped_;
}

D3D12_CPU_DESCRIPTOR_HANDLE Buffer::view(rhi::BindingType type, rhi::BufferRange range) {
    const uint64_t size = rhi::validateBufferBinding(type, *this, range);
    std::lock_guard lock(viewMutex_);
    const auto key = std::make_tuple(type, range.offset, size);
    if (const auto it = views_.find(key); it != views_.end()) {
        return it->second;
    }
    const D3D12_CPU_DESCRIPTOR_HANDLE handle = createView(type, range.offset, size);
    views_.emplace(key, handle);
    return handle;
}

D3D12_CPU_DESCRIPTOR_HANDLE Buffer::wholeRawUav() {
    if (desc_.memory != rhi::MemoryType::GpuOnly) {
        throw rhi::Error("buffer '" + desc_.debugName + "': only GpuOnly buffers take UAVs on D3D12");
    }
    std::lock_guard lock(viewMutex_);
    // A key no binding produces: the fill view is not range-checked against a usage.
    const auto key = std::make_tuple(rhi::BindingType::Sampler, uint64_t(0), desc_.size);
    if (const auto it = views_.find(key); it != views_.end()) {
        return it->second;
    }
    const D3D12_CPU_DESCRIPTOR_HANDLE handle = createView(rhi::BindingType::RawBufferUAV, 0, desc_.size);
    views_.emplace(key, handle);
    return handle;
}

D3D12_CPU_DESCRIPTOR_HANDLE Buffer::createView(rhi::BindingType type, uint64_t offset, uint64_t size) {
    ID3D12Device* device = context_->device();
    const D3D12_CPU_DESCRIPTOR_HANDLE handle = context_->stagingViews().allocate();
    switch (type) {
    case rhi::BindingType::ConstantBuffer: {
        D3D12_CONSTANT_BUFFER_VIEW_DESC cbv{};
        cbv.BufferLocation = gpuAddress() + offset;
        cbv.SizeInBytes = static_cast<UINT>(alignUp(size, kConstantBufferAlignment));
        device->CreateConstantBufferView(&cbv, handle);
        break;
    }
    case rhi::BindingType::BufferSRV:
    case rhi::BindingType::RawBufferSRV: {
        D3D12_SHADER_RESOURCE_VIEW_DESC srv{};
        srv.ViewDimension = D3D12_SRV_DIMENSION_BUFFER;
        srv.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
        if (type == rhi::BindingType::BufferSRV) {
            srv.Format = DXGI_FORMAT_UNKNOWN;
            srv.Buffer.FirstElement = offset / desc_.structStride;
            srv.Buffer.NumElements = static_cast<UINT>(size / desc_.structStride);
            srv.Buffer.StructureByteStride = desc_.structStride;
        } else {
            srv.Format = DXGI_FORMAT_R32_TYPELESS;
            srv.Buffer.FirstElement = offset / 4;
            srv.Buffer.NumElements = static_cast<UINT>(size / 4);
            srv.Buffer.Flags = D3D12_BUFFER_SRV_FLAG_RAW;
        }
        device->CreateShaderResourceView(resource_.Get(), &srv, handle);
        break;
    }
    default: {
        D3D12_UNORDERED_ACCESS_VIEW_DESC uav{};
        uav.ViewDimension = D3D12_UAV_DIMENSION_BUFFER;
        if (type == rhi::BindingType::BufferUAV) {
            uav.Format = DXGI_FORMAT_UNKNOWN;
            uav.Buffer.FirstElement = offset / desc_.structStride;
            uav.Buffer.NumElements = static_cast<UINT>(size / desc_.structStride);
            uav.Buffer.StructureByteStride = desc_.structStride;
        } else {
            uav.Format = DXGI_FORMAT_R32_TYPELESS;
            uav.Buffer.FirstElement = offset / 4;
            uav.Buffer.NumElements = static_cast<UINT>(size / 4);
            uav.Buffer.Flags = D3D12_BUFFER_UAV_FLAG_RAW;
        }
        device->CreateUnorderedAccessView(resource_.Get(), nullptr, &uav, handle);
        break;
    }
    }
    return handle;
}

Buffer& toBuffer(rhi::IBuffer& buffer) {
    if (auto* native = dynamic_cast<Buffer*>(&buffer)) {
        return *native;
    }
    throw rhi::Error("buffer '" + buffer.debugName() + "' does not belong to a D3D12 device");
}

} // namespace lumina::d3d12
