#pragma once
// Analytic references shared by the SDF tests.
#include "gi/sdf/mesh_sdf.h"

#include <glm/glm.hpp>

namespace lumina::sdf::test {

inline float boxDistance(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 centre = 0.5f * (lo + hi), half = 0.5f * (hi - lo);
    const glm::vec3 q = glm::abs(p - centre) - half;
    return glm::length(glm::max(q, glm::vec3(0.0f))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

inline float sphereDistance(const glm::vec3& p, const glm::vec3& centre, float radius) {
    return glm::length(p - centre) - radius;
}

// Trilinear interpolation of a MeshSdf's own grid (no atlas), clamped like the GPU sampler.
inline float sampleGrid(const MeshSdf& sdf, const glm::vec3& p) {
    const glm::vec3 local =
        glm::clamp((p - sdf.volumeMin) / sdf.voxelSize, glm::vec3(0.5f), glm::vec3(sdf.dims) - 0.5f) - 0.5f;
    const glm::uvec3 base = glm::min(glm::uvec3(local), sdf.dims - 1u);
    const glm::uvec3 next = glm::min(base + 1u, sdf.dims - 1u);
    const glm::vec3 f = local - glm::vec3(base);
    float result = 0.0f;
    for (int c = 0; c < 8; ++c) {
        const glm::uvec3 v((c & 1) ? next.x : base.x, (c & 2) ? next.y : base.y, (c & 4) ? next.z : base.z);
        const float w =
            ((c & 1) ? f.x : 1.0f - f.x) * ((c & 2) ? f.y : 1.0f - f.y) * ((c & 4) ? f.z : 1.0f - f.z);
        result += w * sdf.at(v.x, v.y, v.z);
    }
    return result;
}

} // namespace lumina::sdf::test
