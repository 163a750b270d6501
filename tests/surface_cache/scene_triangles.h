#pragma once
// Every triangle of a scene in world space, with the instance it belongs to and its geometric
// (front-face) normal: the surface points the card tests ask owners for.
#include "gi/scene/scene.h"

#include <glm/glm.hpp>
#include <vector>

namespace lumina::surface_cache::test {

struct WorldTriangle {
    uint32_t instance = 0;
    glm::vec3 a, b, c;
    glm::vec3 normal; // unit, from the counter-clockwise winding (mirrors flip it back)
};

inline std::vector<WorldTriangle> worldTriangles(const scene::Scene& scene) {
    std::vector<WorldTriangle> out;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        const scene::Mesh& mesh = scene.meshes[instance.mesh];
        const bool mirrored = glm::determinant(glm::mat3(instance.transform)) < 0.0f;
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            WorldTriangle tri;
            tri.instance = i;
            tri.a = glm::vec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[t]], 1.0f));
            tri.b = glm::vec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[t + 1]], 1.0f));
            tri.c = glm::vec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[t + 2]], 1.0f));
            const glm::vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
            tri.normal = mirrored ? -n : n;
            out.push_back(tri);
        }
    }
    return out;
}

} // namespace lumina::surface_cache::test
