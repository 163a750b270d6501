#pragma once
// The scene on the GPU, uploaded once and shared by every renderer (deferred, path tracer,
// surface cache): one vertex buffer, one index buffer of absolute indices, instances,
// materials, material textures in one 2D texture array (lavapipe has no descriptor
// indexing, so "bindless" is a layer index), the sky, and the draw list. Instance transforms
// and material emission change in place (a dynamic scene, docs/dynamic_scenes.md); geometry,
// textures and the draw list do not.
#include "gi/scene/scene.h"
#include "rhi/rhi.h"
#include "shaders/common/scene_shared.h"

#include <cstdint>
#include <vector>

namespace lumina::gi {

// One draw: a submesh of one instance.
struct SceneDraw {
    rhi::DrawArgs args; // indexed: firstVertexOrIndex and vertexOrIndexCount in the index buffer
    gpu::GpuDrawConstants constants;
};

struct GpuSceneStats {
    uint64_t vertexBytes = 0;
    uint64_t indexBytes = 0;
    uint64_t textureBytes = 0;
    uint64_t skyBytes = 0;
    uint32_t textureLayerSize = 0;
};

class GpuScene {
public:
    // Uploads `scene`; throws rhi::Error when it exceeds what the device takes.
    GpuScene(rhi::IDevice& device, const scene::Scene& scene);

    rhi::BufferHandle vertices;         // GpuVertex[]
    rhi::BufferHandle indices;          // uint32 absolute indices (Index usage and structured)
    rhi::BufferHandle instances;        // GpuInstance[]
    rhi::BufferHandle materials;        // GpuMaterial[]
    rhi::TextureHandle textures;        // RGBA8_SRGB 2D array, full mip chain; a white layer when none
    rhi::SamplerHandle materialSampler; // trilinear, wrap
    rhi::TextureHandle sky;             // RGBA32F latitude-longitude radiance (sky_texture.h)

    // Records the upload of one instance's transform or one material's constants: every pass
    // recorded after it (in this or a later frame) reads the new value.
    void recordInstance(rhi::ICommandList& commands, uint32_t index, const scene::Instance& instance);
    void recordMaterial(rhi::ICommandList& commands, uint32_t index, const scene::Material& material);

    const std::vector<SceneDraw>& draws() const { return draws_; }
    const GpuSceneStats& stats() const { return stats_; }

private:
    std::vector<SceneDraw> draws_;
    uint32_t instanceCount_ = 0;
    uint32_t materialCount_ = 0;
    GpuSceneStats stats_;
};

// CPU halves, exposed for tests: the packing the GPU buffers receive.
std::vector<gpu::GpuVertex> packVertices(const scene::Scene& scene, std::vector<uint32_t>& indicesOut,
                                         std::vector<uint32_t>& meshFirstIndexOut);
gpu::GpuInstance packInstance(const scene::Instance& instance);
gpu::GpuMaterial packMaterial(const scene::Material& material);

// Every material texture resampled to one square power-of-two layer size (at most
// maxLayerSize), with a box-filtered mip chain per layer: mip level -> layers -> RGBA8.
struct TextureArrayData {
    uint32_t layerSize = 1;
    uint32_t layers = 1;
    std::vector<std::vector<uint8_t>> mips; // mips[m]: layers x size_m x size_m x 4 bytes
};
TextureArrayData packTextures(const scene::Scene& scene, uint32_t maxLayerSize = 1024);

} // namespace lumina::gi
