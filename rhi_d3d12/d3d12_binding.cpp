#include "rhi_d3d12/d3d12_binding.h"

#include "rhi_d3d12/d3d12_buffer.h"
#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_sampler.h"
#include "rhi_d3d12/d3d12_texture.h"

#include <set>

namespace lumina::d3d12 {

namespace {

D3D12_DESCRIPTOR_RANGE_TYPE rangeType(rhi::BindingType type) {
    switch (rhi::registerClass(type)) {
    case 'b':
        return D3D12_DESCRIPTOR_RANGE_TYPE_CBV;
    case 't':
        return D3D12_DESCRIPTOR_RANGE_TYPE_SRV;
    case 'u':
        return D3D12_DESCRIPTOR_RANGE_TYPE_UAV;
    default:
        return D3D12_DESCRIPTOR_RANGE_TYPE_SAMPLER;
    }
}

D3D12_SHADER_VISIBILITY visibility(rhi::ShaderStageMask mask) {
    switch (mask) {
    case rhi::ShaderStageMask::Vertex:
        return D3D12_SHADER_VISIBILITY_VERTEX;
    case rhi::ShaderStageMask::Pixel:
        return D3D12_SHADER_VISIBILITY_PIXEL;
    default:
        return D3D12_SHADER_VISIBILITY_ALL; // compute only ever sees ALL
    }
}

std::string registerName(const rhi::BindingLayoutItem& item, uint32_t space) {
    return std::string(1, rhi::registerClass(item.type)) + std::to_string(item.reg) + ", space" +
           std::to_string(space);
}

} // namespace

BindingLayout::BindingLayout(const rhi::BindingLayoutDesc& desc) : desc_(desc) {
    if (desc.space == kPushConstantSpace) {
        throw rhi::Error("createBindingLayout: register space 999 is reserved for push constants");
    }
    std::set<std::pair<char, uint32_t>> seen;
    key_ = std::to_string(desc.space) + ":" + std::to_string(int(desc.visibility)) + ":";
    for (const rhi::BindingLayoutItem& item : desc.items) {
        if (!seen.insert({rhi::registerClass(item.type), item.reg}).second) {
            throw rhi::Error("createBindingLayout: register " + registerName(item, desc.space) +
                             " appears twice");
        }
        D3D12_DESCRIPTOR_RANGE range{};
        range.RangeType = rangeType(item.type);
        range.NumDescriptors = 1;
        range.BaseShaderRegister = item.reg;
        range.RegisterSpace = desc.space;
        auto& ranges = item.type == rhi::BindingType::Sampler ? samplerRanges_ : resourceRanges_;
        range.OffsetInDescriptorsFromTableStart = static_cast<UINT>(ranges.size());
        slots_.push_back(range.OffsetInDescriptorsFromTableStart);
        ranges.push_back(range);
        key_ += std::to_string(int(item.type)) + "." + std::to_string(item.reg) + ",";
    }
}

const BindingLayout& toBindingLayout(const rhi::IBindingLayout& layout) {
    if (const auto* native = dynamic_cast<const BindingLayout*>(&layout)) {
        return *native;
    }
    throw rhi::Error("binding layout does not belong to a D3D12 device");
}

RootSignatureHandle RootSignatureCache::get(const std::vector<rhi::BindingLayoutHandle>& layouts,
                                            uint32_t pushConstantBytes, const std::string& debugName) {
    if (pushConstantBytes % 4 != 0 || pushConstantBytes > kMaxPushConstantBytes) {
        throw rhi::Error("'" + debugName + "': pushConstantBytes " + std::to_string(pushConstantBytes) +
                         " is not a multiple of 4 up to 128");
    }
    std::string key = "pc" + std::to_string(pushConstantBytes);
    std::set<uint32_t> spaces;
    for (const rhi::BindingLayoutHandle& layout : layouts) {
        if (!layout) {
            throw rhi::Error("'" + debugName + "': a binding layout is null");
        }
        const BindingLayout& native = toBindingLayout(*layout);
        if (!spaces.insert(native.desc().space).second) {
            throw rhi::Error("'" + debugName + "': two binding layouts use register space " +
                             std::to_string(native.desc().space));
        }
        key += "|" + native.key();
    }
    std::lock_guard lock(mutex_);
    if (const auto it = cache_.find(key); it != cache_.end()) {
        return it->second;
    }
    RootSignatureHandle signature = create(layouts, pushConstantBytes, key, debugName);
    cache_.emplace(key, signature);
    return signature;
}

size_t RootSignatureCache::size() {
    std::lock_guard lock(mutex_);
    return cache_.size();
}

RootSignatureHandle RootSignatureCache::create(const std::vector<rhi::BindingLayoutHandle>& layouts,
                                               uint32_t pushConstantBytes, const std::string& key,
                                               const std::string& debugName) {
    auto signature = std::make_shared<RootSignature>();
    signature->pushConstantBytes = pushConstantBytes;
    signature->key = key;
    std::vector<D3D12_ROOT_PARAMETER> parameters;
    if (pushConstantBytes > 0) {
        D3D12_ROOT_PARAMETER constants{};
        constants.ParameterType = D3D12_ROOT_PARAMETER_TYPE_32BIT_CONSTANTS;
        constants.Constants = {0, kPushConstantSpace, pushConstantBytes / 4};
        constants.ShaderVisibility = D3D12_SHADER_VISIBILITY_ALL;
        parameters.push_back(constants);
    }
    for (const rhi::BindingLayoutHandle& handle : layouts) {
        const BindingLayout& layout = toBindingLayout(*handle);
        RootSignature::Tables tables;
        for (const auto* ranges : {&layout.resourceRanges(), &layout.samplerRanges()}) {
            if (ranges->empty()) {
                continue;
            }
            D3D12_ROOT_PARAMETER table{};
            table.ParameterType = D3D12_ROOT_PARAMETER_TYPE_DESCRIPTOR_TABLE;
            table.DescriptorTable = {static_cast<UINT>(ranges->size()), ranges->data()};
            table.ShaderVisibility = visibility(layout.desc().visibility);
            (ranges == &layout.resourceRanges() ? tables.resources : tables.samplers) =
                int(parameters.size());
            parameters.push_back(table);
        }
        signature->tables.push_back(tables);
    }
    D3D12_ROOT_SIGNATURE_DESC desc{};
    desc.NumParameters = static_cast<UINT>(parameters.size());
    desc.pParameters = parameters.data();
    desc.Flags = D3D12_ROOT_SIGNATURE_FLAG_NONE;
    ComPtr<ID3DBlob> blob;
    ComPtr<ID3DBlob> errors;
    const HRESULT hr = D3D12SerializeRootSignature(&desc, D3D_ROOT_SIGNATURE_VERSION_1, &blob, &errors);
    if (FAILED(hr)) {
        std::string message = "D3D12SerializeRootSignature('" + debugName + "') failed: " + hresultText(hr);
        if (errors && errors->GetBufferSize()) {
            message += ": " + std::string(static_cast<const char*>(errors->GetBufferPointer()),
                                          errors->GetBufferSize());
        }
        throw rhi::Error(message);
    }
    check(context_->device()->CreateRootSignature(0, blob->GetBufferPointer(), blob->GetBufferSize(),
                                                  IID_PPV_ARGS(&signature->native)),
          "ID3D12Device::CreateRootSignature('" + debugName + "')", *context_);
    setDebugName(signature->native.Get(), "root signature of " + debugName);
    return signature;
}

WrittenBindingSet writeBindingSet(ID3D12Device* device, const BindingLayout& layout,
                                  const rhi::BindingSet& set, DescriptorTableAllocator& views,
                                  DescriptorTableAllocator& samplers) {
    const uint32_t space = layout.desc().space;
    if (set.layout && set.layout.get() != &layout && toBindingLayout(*set.layout).key() != layout.key()) {
        throw rhi::Error("binding set for space " + std::to_string(space) +
                         " was made for a different binding layout than the pipeline's");
    }
    WrittenBindingSet written;
    DescriptorTable viewTable;
    if (!layout.resourceRanges().empty()) {
        viewTable = views.allocate(static_cast<uint32_t>(layout.resourceRanges().size()));
        written.resources = viewTable.gpu;
    }
    // Samplers are gathered first and written as one table the list may already hold.
    std::vector<D3D12_CPU_DESCRIPTOR_HANDLE> samplerSources(layout.samplerRanges().size());
    const UINT viewIncrement =
        device->GetDescriptorHandleIncrementSize(D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV);

    const auto& items = layout.desc().items;
    for (size_t i = 0; i < items.size(); ++i) {
        const rhi::BindingLayoutItem& expected = items[i];
        const rhi::BindingSetItem* item = nullptr;
        for (const rhi::BindingSetItem& candidate : set.items) {
            if (rhi::registerClass(candidate.type) == rhi::registerClass(expected.type) &&
                candidate.reg == expected.reg) {
                item = &candidate;
                break;
            }
        }
        const std::string where = "register " + registerName(expected, space);
        if (!item) {
            throw rhi::Error("binding set leaves " + where + " of its layout unbound");
        }
        if (item->type != expected.type) {
            throw rhi::Error("binding set binds " + where + " as a " + rhi::bindingTypeName(item->type) +
                             ", the layout declares a " + rhi::bindingTypeName(expected.type));
        }
        D3D12_CPU_DESCRIPTOR_HANDLE source{};
        const rhi::TextureDimension* dimension = item->overrideDimension ? &item->viewDimension : nullptr;
        switch (item->type) {
        case rhi::BindingType::ConstantBuffer:
        case rhi::BindingType::BufferSRV:
        case rhi::BindingType::RawBufferSRV:
        case rhi::BindingType::BufferUAV:
        case rhi::BindingType::RawBufferUAV:
            if (!item->buffer) {
                throw rhi::Error("binding set: " + where + " has no buffer");
            }
            source = toBuffer(*item->buffer).view(item->type, item->range);
            written.uses.push_back({item->buffer.get(), rhi::requiredState(item->type)});
            break;
        case rhi::BindingType::TextureSRV:
        case rhi::BindingType::TextureUAV:
            if (!item->texture) {
                throw rhi::Error("binding set: " + where + " has no texture");
            }
            source = item->type == rhi::BindingType::TextureSRV
                         ? toTexture(*item->texture).srv(item->subresources, dimension)
                         : toTexture(*item->texture).uav(item->subresources.baseMip, dimension);
            written.uses.push_back({item->texture.get(), rhi::requiredState(item->type)});
            break;
        case rhi::BindingType::Sampler:
            if (!item->sampler) {
                throw rhi::Error("binding set: " + where + " has no sampler");
            }
            source = toSampler(*item->sampler).descriptor();
            break;
        }
        if (item->type == rhi::BindingType::Sampler) {
            samplerSources[layout.slot(i)] = source;
        } else {
            device->CopyDescriptorsSimple(1, {viewTable.cpu.ptr + size_t(layout.slot(i)) * viewIncrement},
                                          source, D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV);
        }
    }
    if (!samplerSources.empty()) {
        written.samplers = samplers.tableOf(device, samplerSources).gpu;
    }
    return written;
}

} // namespace lumina::d3d12
