#include "gi/gpu_scene/gpu_scene.h"

#include "gi/gpu_scene/sky_texture.h"

#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

gpu::float4 row(const glm::mat4& m, int r) {
    return {m[0][r], m[1][r], m[2][r], m[3][r]};
}

} // namespace

std::vector<gpu::GpuVertex> packVertices(const scene::Scene& scene, std::vector<uint32_t>& indicesOut,
                                         std::vector<uint32_t>& meshFirstIndexOut) {
    std::vector<gpu::GpuVertex> vertices;
    vertices.reserve(scene.vertexCount());
    indicesOut.clear();
    meshFirstIndexOut.clear();
    for (const scene::Mesh& mesh : scene.meshes) {
        const auto base = static_cast<uint32_t>(vertices.size());
        meshFirstIndexOut.push_back(static_cast<uint32_t>(indicesOut.size()));
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::vec2 uv = v < mesh.uvs.size() ? mesh.uvs[v] : glm::vec2(0.0f);
            vertices.push_back({gpu::float4(mesh.positions[v], uv.x), gpu::float4(mesh.normals[v], uv.y)});
        }
        for (uint32_t index : mesh.indices) {
            indicesOut.push_back(base + index);
        }
    }
    return vertices;
}

gpu::GpuInstance packInstance(const scene::Instance& instance) {
    gpu::GpuInstance out{};
    const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(instance.transform));
    for (int r = 0; r < 3; ++r) {
        out.objectToWorld[r] = row(instance.transform, r);
        out.normalToWorld[r] = gpu::float4(normalMatrix[0][r], normalMatrix[1][r], normalMatrix[2][r], 0.0f);
    }
    out.info =
        gpu::uint4(instance.mesh, glm::determinant(glm::mat3(instance.transform)) < 0.0f ? 1u : 0u, 0u, 0u);
    return out;
}

gpu::GpuMaterial packMaterial(const scene::Material& material) {
    gpu::GpuMaterial out{};
    out.baseColor = material.baseColor;
    out.emission = gpu::float4(material.emission, 0.0f);
    auto layer = [](uint32_t texture) {
        return texture == scene::kNoTexture ? LUMINA_NO_TEXTURE_LAYER : texture;
    };
    out.textures = gpu::uint4(layer(material.baseColorTexture), layer(material.emissionTexture),
                              material.doubleSided ? LUMINA_MATERIAL_DOUBLE_SIDED : 0u, 0u);
    return out;
}

GpuScene::GpuScene(rhi::IDevice& device, const scene::Scene& scene) {
    std::vector<uint32_t> indexData;
    std::vector<uint32_t> meshFirstIndex;
    const std::vector<gpu::GpuVertex> vertexData = packVertices(scene, indexData, meshFirstIndex);
    if (vertexData.empty() || indexData.empty()) {
        throw rhi::Error("scene '" + scene.name + "' has no triangles to upload");
    }

    std::vector<gpu::GpuInstance> instanceData;
    for (const scene::Instance& instance : scene.instances) {
        instanceData.push_back(packInstance(instance));
    }
    std::vector<gpu::GpuMaterial> materialData;
    for (const scene::Material& material : scene.materials) {
        materialData.push_back(packMaterial(material));
    }
    if (materialData.empty()) {
        materialData.push_back(packMaterial(scene::Material{}));
    }

    instanceCount_ = uint32_t(instanceData.size());
    materialCount_ = uint32_t(scene.materials.size());
    const auto structured = rhi::BufferUsage::Structured;
    vertices = rhi::createBufferWithData(
        device, {.structStride = sizeof(gpu::GpuVertex), .usage = structured, .debugName = "scene vertices"},
        vertexData.data(), vertexData.size() * sizeof(gpu::GpuVertex));
    indices = rhi::createBufferWithData(device,
                                        {.structStride = sizeof(uint32_t),
                                         .usage = structured | rhi::BufferUsage::Index,
                                         .debugName = "scene indices"},
                                        indexData.data(), indexData.size() * sizeof(uint32_t));
    instances = rhi::createBufferWithData(
        device,
        {.structStride = sizeof(gpu::GpuInstance), .usage = structured, .debugName = "scene instances"},
        instanceData.data(), instanceData.size() * sizeof(gpu::GpuInstance));
    materials = rhi::createBufferWithData(
        device,
        {.structStride = sizeof(gpu::GpuMaterial), .usage = structured, .debugName = "scene materials"},
        materialData.data(), materialData.size() * sizeof(gpu::GpuMaterial));

    const TextureArrayData textureData = packTextures(scene);
    textures = device.createTexture({.dimension = rhi::TextureDimension::Texture2DArray,
                                     .format = rhi::Format::RGBA8_SRGB,
                                     .width = textureData.layerSize,
                                     .height = textureData.layerSize,
                                     .arrayLayers = textureData.layers,
                                     .mipLevels = uint32_t(textureData.mips.size()),
                                     .usage = rhi::TextureUsage::Sampled,
                                     .debugName = "scene material textures"});
    rhi::CommandListHandle upload = device.createCommandList();
    upload->begin();
    for (uint32_t mip = 0; mip < textureData.mips.size(); ++mip) {
        const size_t layerBytes = textureData.mips[mip].size() / textureData.layers;
        for (uint32_t layer = 0; layer < textureData.layers; ++layer) {
            upload->writeTexture(*textures, {mip, layer}, textureData.mips[mip].data() + layer * layerBytes);
        }
    }
    upload->end();
    rhi::IQueue& queue = device.queue(rhi::QueueType::Graphics);
    queue.waitForValue(queue.submit(*upload));

    const SkyTextureData skyData = packSky(scene);
    sky = createSkyTexture(device, skyData);
    stats_.skyBytes = skyData.texels.size() * sizeof(gpu::float4);

    materialSampler = device.createSampler({.addressU = rhi::AddressMode::Wrap,
                                            .addressV = rhi::AddressMode::Wrap,
                                            .addressW = rhi::AddressMode::Wrap,
                                            .debugName = "material sampler"});

    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        const scene::Mesh& mesh = scene.meshes.at(instance.mesh);
        for (const scene::Submesh& submesh : mesh.submeshes) {
            SceneDraw draw{};
            draw.args.vertexOrIndexCount = submesh.indexCount;
            draw.args.firstVertexOrIndex = meshFirstIndex[instance.mesh] + submesh.firstIndex;
            draw.constants = {i, std::min<uint32_t>(submesh.material, uint32_t(materialData.size() - 1)), 0,
                              0};
            draws_.push_back(draw);
        }
    }

    stats_.vertexBytes = vertexData.size() * sizeof(gpu::GpuVertex);
    stats_.indexBytes = indexData.size() * sizeof(uint32_t);
    for (const auto& mip : textureData.mips) {
        stats_.textureBytes += mip.size();
    }
    stats_.textureLayerSize = textureData.layerSize;
}

namespace {

// Records the upload of element `index` of a structured buffer of `count` elements.
template <typename T>
void recordElement(rhi::ICommandList& commands, rhi::IBuffer& buffer, const char* what, uint32_t index,
                   uint32_t count, const T& value) {
    if (index >= count) {
        throw std::out_of_range(std::string("GpuScene: ") + what + " " + std::to_string(index) + " of " +
                                std::to_string(count));
    }
    commands.writeBuffer(buffer, &value, sizeof(T), uint64_t(index) * sizeof(T));
}

} // namespace

void GpuScene::recordInstance(rhi::ICommandList& commands, uint32_t index, const scene::Instance& instance) {
    recordElement(commands, *instances, "instance", index, instanceCount_, packInstance(instance));
}

void GpuScene::recordMaterial(rhi::ICommandList& commands, uint32_t index, const scene::Material& material) {
    recordElement(commands, *materials, "material", index, materialCount_, packMaterial(material));
}

} // namespace lumina::gi
