#include "gi/pathtracer/trace_geometry.h"

#include "gi/pathtracer/alias_table.h"
#include "shaders/common/conventions.h"

#include <algorithm>
#include <numbers>
#include <stdexcept>
#include <string>

namespace lumina::gi {

TraceGeometry buildTraceGeometry(const scene::Scene& scene) {
    TraceGeometry out;
    std::vector<uint32_t> meshFirstIndex;
    uint64_t indexCount = 0;
    for (const scene::Mesh& mesh : scene.meshes) {
        meshFirstIndex.push_back(uint32_t(indexCount));
        indexCount += mesh.indices.size();
    }
    if (indexCount > UINT32_MAX) {
        throw std::invalid_argument("scene '" + scene.name + "': " + std::to_string(indexCount) +
                                    " indices do not fit the 32-bit index buffer");
    }
    const uint64_t triangleCount = scene.triangleCount();
    if (triangleCount >= (uint64_t(1) << 32) - 1) {
        throw std::invalid_argument("scene '" + scene.name + "': too many triangles to trace");
    }
    const uint32_t materialCount = std::max<uint32_t>(uint32_t(scene.materials.size()), 1u);
    if (materialCount > (1u << 24)) {
        throw std::invalid_argument("scene '" + scene.name + "': more than 2^24 materials");
    }
    out.triangles.reserve(triangleCount);
    out.refs.reserve(triangleCount);
    std::vector<double> emitterWeights;

    for (uint32_t instanceIndex = 0; instanceIndex < scene.instances.size(); ++instanceIndex) {
        const scene::Instance& instance = scene.instances[instanceIndex];
        const scene::Mesh& mesh = scene.meshes.at(instance.mesh);
        const bool mirrored = glm::determinant(glm::mat3(instance.transform)) < 0.0f;
        std::vector<glm::vec3> world(mesh.positions.size());
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            world[v] = glm::vec3(instance.transform * glm::vec4(mesh.positions[v], 1.0f));
        }
        for (const scene::Submesh& submesh : mesh.submeshes) {
            const uint32_t material = std::min(submesh.material, materialCount - 1u);
            const glm::vec3 emission =
                material < scene.materials.size() ? scene.materials[material].emission : glm::vec3(0.0f);
            const bool doubleSided =
                material < scene.materials.size() && scene.materials[material].doubleSided;
            const float emittedLuminance = gpu::luminance(emission);
            for (uint32_t i = submesh.firstIndex; i + 2 < submesh.firstIndex + submesh.indexCount; i += 3) {
                const glm::vec3 v0 = world[mesh.indices[i]];
                const glm::vec3 v1 = world[mesh.indices[i + 1]];
                const glm::vec3 v2 = world[mesh.indices[i + 2]];
                const auto primId = uint32_t(out.refs.size());
                out.triangles.push_back({v0, v1, v2, primId});
                gpu::PtTriangle ref{};
                ref.info = gpu::uint4(instanceIndex, meshFirstIndex[instance.mesh] + i,
                                      (mirrored ? LUMINA_PT_TRIANGLE_MIRRORED : 0u) | (material << 8u),
                                      LUMINA_PT_NOT_EMISSIVE);
                const glm::vec3 edge1 = v1 - v0;
                const glm::vec3 edge2 = v2 - v0;
                const float area = 0.5f * glm::length(glm::cross(edge1, edge2));
                if (emittedLuminance > 0.0f && area > 0.0f) {
                    ref.info.w = uint32_t(out.emitters.size());
                    gpu::PtEmitter emitter{};
                    emitter.v0AndArea = glm::vec4(v0, area);
                    emitter.edge1AndPdf = glm::vec4(edge1, 0.0f);
                    emitter.edge2AndSign = glm::vec4(edge2, mirrored ? -1.0f : 1.0f);
                    emitter.info = gpu::uint4(primId, 0u, 0u, 0u);
                    out.emitters.push_back(emitter);
                    const double power = double(emittedLuminance) * double(area) * std::numbers::pi *
                                         (doubleSided ? 2.0 : 1.0);
                    emitterWeights.push_back(power);
                    out.emittedPower += power;
                }
                out.refs.push_back(ref);
            }
        }
    }
    if (!out.emitters.empty()) {
        AliasTable table = buildAliasTable(emitterWeights);
        out.emitterAlias = std::move(table.entries);
        for (size_t i = 0; i < out.emitters.size(); ++i) {
            out.emitters[i].edge1AndPdf.w = table.pdf[i];
        }
    }
    return out;
}

} // namespace lumina::gi
