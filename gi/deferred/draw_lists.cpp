#include "gi/deferred/draw_lists.h"

#include "shaders/deferred/deferred_shared.h"

namespace lumina::gi {

std::vector<GBufferDrawGroup> gbufferDrawGroups(const scene::Scene& scene, std::span<const SceneDraw> draws) {
    GBufferDrawGroup back{rhi::CullMode::Back, {}};
    GBufferDrawGroup front{rhi::CullMode::Front, {}};
    GBufferDrawGroup none{rhi::CullMode::None, {}};
    for (const SceneDraw& draw : draws) {
        const uint32_t material = draw.constants.material;
        const bool doubleSided = material < scene.materials.size() && scene.materials[material].doubleSided;
        const bool mirrored =
            glm::determinant(glm::mat3(scene.instances.at(draw.constants.instance).transform)) < 0.0f;
        GBufferDrawGroup& group = doubleSided ? none : mirrored ? front : back;
        group.draws.push_back(RasterDraw::with(draw.args, draw.constants));
    }
    std::vector<GBufferDrawGroup> groups;
    for (GBufferDrawGroup* group : {&back, &front, &none}) {
        if (!group->draws.empty()) {
            groups.push_back(std::move(*group));
        }
    }
    return groups;
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
