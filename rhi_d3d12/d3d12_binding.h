#pragma once
// Binding layouts and root signatures. A pipeline's root signature is built from its binding
// layouts, register for register: root constants (the push constants) at b0 in space 999
// (shaders/common/bindings.hlsli, LUMINA_PUSH_CONSTANTS), then for each layout one descriptor
// table for its CBVs, SRVs and UAVs and one for its samplers (D3D12 keeps samplers in heaps
// of their own), each table holding the layout's items in declaration order.
#include "rhi/binding.h"
#include "rhi_d3d12/d3d12_context.h"
#include "rhi_d3d12/d3d12_descriptor_heap.h"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace lumina::d3d12 {

// The register space of root constants; shaders/common/bindings.hlsli's LUMINA_PUSH_CONSTANT_SPACE.
constexpr uint32_t kPushConstantSpace = 999;
constexpr uint32_t kMaxPushConstantBytes = 128;

class BindingLayout final : public rhi::IBindingLayout {
public:
    explicit BindingLayout(const rhi::BindingLayoutDesc& desc);
    const rhi::BindingLayoutDesc& desc() const override { return desc_; }

    const std::vector<D3D12_DESCRIPTOR_RANGE>& resourceRanges() const { return resourceRanges_; }
    const std::vector<D3D12_DESCRIPTOR_RANGE>& samplerRanges() const { return samplerRanges_; }
    // Item i's offset in its table (the resource table or the sampler table).
    uint32_t slot(size_t item) const { return slots_[item]; }
    // Identical descriptions make interchangeable layouts.
    const std::string& key() const { return key_; }

private:
    rhi::BindingLayoutDesc desc_;
    std::vector<D3D12_DESCRIPTOR_RANGE> resourceRanges_;
    std::vector<D3D12_DESCRIPTOR_RANGE> samplerRanges_;
    std::vector<uint32_t> slots_;
    std::string key_;
};

const BindingLayout& toBindingLayout(const rhi::IBindingLayout& layout);

// A root signature and where each layout's tables sit in it.
struct RootSignature {
    ComPtr<ID3D12RootSignature> native;
    uint32_t pushConstantBytes = 0;
    static constexpr uint32_t kPushConstantParameter = 0; // when pushConstantBytes > 0
    struct Tables {
        int resources = -1; // root parameter index, -1: the layout has none
        int samplers = -1;
    };
    std::vector<Tables> tables; // per pipeline layout, in order
    std::string key;
};
using RootSignatureHandle = std::shared_ptr<const RootSignature>;

// Root signatures by layout contents and push-constant size, shared by every pipeline (and
// every binding layout, which creates its own one-layout signature to validate itself).
class RootSignatureCache {
public:
    explicit RootSignatureCache(ContextHandle context) : context_(std::move(context)) {}
    RootSignatureHandle get(const std::vector<rhi::BindingLayoutHandle>& layouts, uint32_t pushConstantBytes,
                            const std::string& debugName);
    size_t size();

private:
    RootSignatureHandle create(const std::vector<rhi::BindingLayoutHandle>& layouts,
                               uint32_t pushConstantBytes, const std::string& key,
                               const std::string& debugName);

    ContextHandle context_;
    std::mutex mutex_;
    std::map<std::string, RootSignatureHandle> cache_;
};

// A binding set written into descriptor tables: the GPU handles to bind, and every resource it
// uses with the state it must be in.
struct WrittenBindingSet {
    D3D12_GPU_DESCRIPTOR_HANDLE resources{};
    D3D12_GPU_DESCRIPTOR_HANDLE samplers{};
    struct Use {
        rhi::IResource* resource;
        rhi::ResourceState state;
    };
    std::vector<Use> uses;
};

// Copies the set's views (created on first use) into tables from the two allocators. The set
// must provide every item of `layout`, with the same binding type per register; throws
// rhi::Error naming the register otherwise.
WrittenBindingSet writeBindingSet(ID3D12Device* device, const BindingLayout& layout,
                                  const rhi::BindingSet& set, DescriptorTableAllocator& views,
                                  DescriptorTableAllocator& samplers);

} // namespace lumina::d3d12
