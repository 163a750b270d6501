#include "gi/deferred/draw_lists.h"

#include "shaders/deferred/deferred_shared.h"

namespace lumina::gi {

GBufferDraws gbufferDraws(const scene::Scene& scene, std::span<const SceneDraw> draws) {
    std::vector<const SceneDraw*> back, front, none;
    for (const SceneDraw& draw : draws) {
        const uint32_t material = draw.constants.material;
        const bool doubleSided = material < scene.materials.size() && scene.materials[material].doubleSided;
        const bool mirrored =
            glm::determinant(glm::mat3(scene.instances.at(draw.constants.instance).transform)) < 0.0f;
        (doubleSided ? none : mirrored ? front : back).push_back(&draw);
    }
    GBufferDraws out;
    uint64_t nextId = 1;
    for (const auto& [cull, members] : {std::pair{rhi::CullMode::Back, &back},
                                        {rhi::CullMode::Front, &front},
                                        {rhi::CullMode::None, &none}}) {
        if (members->empty()) {
            continue;
        }
        GBufferDrawGroup group{cull, {}};
        for (const SceneDraw* draw : *members) {
            const auto firstId = uint32_t(nextId);
            group.draws.push_back(RasterDraw::with(
                draw->args, gpu::GBufferVisibilityDrawConstants{draw->constants.instance, firstId, 0u, 0u}));
            out.resolveTable.push_back(
                {firstId, draw->args.firstVertexOrIndex, draw->constants.instance, draw->constants.material});
            nextId += draw->args.vertexOrIndexCount / 3;
        }
        out.groups.push_back(std::move(group));
    }
    out.triangleCount = nextId - 1;
    return out;
}

std::vector<ShadowDraw> shadowDraws(std::span<const SceneDraw> draws) {
    std::vector<ShadowDraw> out;
    for (const SceneDraw& draw : draws) {
        if (!out.empty() && out.back().instance == draw.constants.instance &&
            out.back().args.firstVertexOrIndex + out.back().args.vertexOrIndexCount ==
                draw.args.firstVertexOrIndex) {
            out.back().args.vertexOrIndexCount += draw.args.vertexOrIndexCount;
            continue;
        }
        out.push_back({draw.args, draw.constants.instance});
    }
    return out;
}

std::vector<RasterDraw> shadowRasterDraws(const std::vector<ShadowDraw>& draws, uint32_t layer) {
    std::vector<RasterDraw> out;
    out.reserve(draws.size());
    for (const ShadowDraw& draw : draws) {
        out.push_back(RasterDraw::with(draw.args, gpu::ShadowDrawConstants{draw.instance, layer, 0u, 0u}));
    }
    return out;
}

} // namespace lumina::gi
