#include "gi/core/pipeline_cache.h"

#include "gi/core/kernel_bindings.h"

#include <algorithm>

namespace lumina::gi {

namespace {

void appendKey(std::string& key, const void* data, size_t size) {
    key.append(static_cast<const char*>(data), size);
}

std::string rasterKey(const RasterPipelineState& state, const std::vector<rhi::Format>& colorFormats,
                      rhi::Format depthFormat) {
    std::string key;
    appendKey(key, &state.raster, sizeof(state.raster));
    appendKey(key, &state.depth, sizeof(state.depth));
    for (const rhi::BlendState& blend : state.blend) {
        appendKey(key, &blend, sizeof(blend));
    }
    appendKey(key, &state.topology, sizeof(state.topology));
    for (rhi::Format format : colorFormats) {
        key += static_cast<char>(format);
    }
    key += static_cast<char>(depthFormat);
    return key;
}

} // namespace

void PipelineCache::checkBindings(std::string_view kernel, const SpaceBindings& bindings) {
    const std::vector<uint32_t> spirv = readKernelSpirv(shaders_.directory().string(), kernel);
    if (!spirv.empty()) {
        checkKernelBindings(kernel, kernelResources(kernel, spirv), bindings);
    }
}

std::vector<rhi::BindingLayoutHandle> PipelineCache::layoutsFor(const SpaceBindings& bindings,
                                                                std::string& key) {
    std::vector<rhi::BindingLayoutHandle> layouts;
    for (uint32_t space = 0; space < bindings.size(); ++space) {
        rhi::BindingLayoutDesc desc;
        desc.space = space;
        for (const rhi::BindingSetItem& item : bindings[space]) {
            desc.items.push_back({item.type, item.reg});
        }
        std::sort(desc.items.begin(), desc.items.end(), [](const auto& a, const auto& b) {
            return a.type != b.type ? a.type < b.type : a.reg < b.reg;
        });
        std::string layoutKey = std::to_string(space) + ":";
        for (const auto& item : desc.items) {
            layoutKey += std::to_string(int(item.type)) + "/" + std::to_string(item.reg) + ",";
        }
        key += layoutKey + ";";
        auto it = layouts_.find(layoutKey);
        if (it == layouts_.end()) {
            it = layouts_.emplace(layoutKey, device_.createBindingLayout(desc)).first;
        }
        layouts.push_back(it->second);
    }
    return layouts;
}

const PipelineCache::ComputeEntry&
PipelineCache::compute(std::string_view kernel, const SpaceBindings& bindings, uint32_t pushConstantBytes) {
    std::string key = std::string(kernel) + "|" + std::to_string(pushConstantBytes) + "|";
    auto layouts = layoutsFor(bindings, key);
    if (const auto it = compute_.find(key); it != compute_.end()) {
        return it->second;
    }
    checkBindings(kernel, bindings);
    ComputeEntry entry;
    entry.layouts = std::move(layouts);
    entry.pipeline = device_.createComputePipeline({.shader = shaders_.get(kernel),
                                                    .layouts = entry.layouts,
                                                    .pushConstantBytes = pushConstantBytes,
                                                    .debugName = std::string(kernel)});
    return compute_.emplace(std::move(key), std::move(entry)).first->second;
}

const PipelineCache::GraphicsEntry&
PipelineCache::graphics(std::string_view vertexKernel, std::string_view pixelKernel,
                        const SpaceBindings& bindings, uint32_t pushConstantBytes,
                        const RasterPipelineState& state, const std::vector<rhi::Format>& colorFormats,
                        rhi::Format depthFormat) {
    std::string key = std::string(vertexKernel) + "|" + std::string(pixelKernel) + "|" +
                      std::to_string(pushConstantBytes) + "|" + rasterKey(state, colorFormats, depthFormat) +
                      "|";
    auto layouts = layoutsFor(bindings, key);
    if (const auto it = graphics_.find(key); it != graphics_.end()) {
        return it->second;
    }
    checkBindings(vertexKernel, bindings);
    if (!pixelKernel.empty()) {
        checkBindings(pixelKernel, bindings);
    }
    GraphicsEntry entry;
    entry.layouts = std::move(layouts);
    rhi::GraphicsPipelineDesc desc;
    desc.vertexShader = shaders_.get(vertexKernel, rhi::ShaderStage::Vertex);
    if (!pixelKernel.empty()) {
        desc.pixelShader = shaders_.get(pixelKernel, rhi::ShaderStage::Pixel);
    }
    desc.layouts = entry.layouts;
    desc.pushConstantBytes = pushConstantBytes;
    desc.topology = state.topology;
    desc.raster = state.raster;
    desc.depth = state.depth;
    desc.blend = state.blend;
    desc.colorFormats = colorFormats;
    desc.depthFormat = depthFormat;
    desc.debugName = std::string(vertexKernel) + " + " + std::string(pixelKernel);
    entry.pipeline = device_.createGraphicsPipeline(desc);
    return graphics_.emplace(std::move(key), std::move(entry)).first->second;
}

} // namespace lumina::gi
