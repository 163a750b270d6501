#include "gi/scene/mesh_repair.h"

#include <algorithm>
#include <cmath>

namespace lumina::scene {

namespace {

// A face normal scaled by twice the triangle's area, in double so that thin triangles keep
// their direction.
glm::dvec3 areaNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
}

bool usable(const glm::vec3& n) {
    const float length2 = glm::dot(n, n);
    return std::isfinite(length2) && length2 > 1e-12f;
}

} // namespace

bool isDegenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 pa(a), pb(b), pc(c);
    const double longest2 =
        std::max({glm::dot(pb - pa, pb - pa), glm::dot(pc - pb, pc - pb), glm::dot(pa - pc, pa - pc)});
    const double twiceArea = glm::length(glm::cross(pb - pa, pc - pa));
    return !(twiceArea > kDegenerateRelativeArea * longest2);
}

uint64_t dropDegenerateTriangles(std::vector<uint32_t>& indices, std::span<const glm::vec3> positions) {
    size_t kept = 0;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
        if (i0 == i1 || i1 == i2 || i0 == i2 || isDegenerate(positions[i0], positions[i1], positions[i2])) {
            continue;
        }
        indices[kept++] = i0;
        indices[kept++] = i1;
        indices[kept++] = i2;
    }
    const uint64_t dropped = (indices.size() - kept) / 3;
    indices.resize(kept);
    return dropped;
}

void makeFlatShaded(std::vector<glm::vec3>& positions, std::vector<glm::vec2>& uvs,
                    std::vector<glm::vec3>& normals, std::vector<uint32_t>& indices) {
    std::vector<glm::vec3> flatPositions;
    std::vector<glm::vec2> flatUvs;
    std::vector<glm::vec3> flatNormals;
    flatPositions.reserve(indices.size());
    flatNormals.reserve(indices.size());
    if (!uvs.empty()) {
        flatUvs.reserve(indices.size());
    }
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::vec3 n = glm::vec3(glm::normalize(
            areaNormal(positions[indices[t]], positions[indices[t + 1]], positions[indices[t + 2]])));
        for (size_t k = 0; k < 3; ++k) {
            flatPositions.push_back(positions[indices[t + k]]);
            flatNormals.push_back(n);
            if (!uvs.empty()) {
                flatUvs.push_back(uvs[indices[t + k]]);
            }
        }
    }
    for (size_t i = 0; i < indices.size(); ++i) {
        indices[i] = uint32_t(i);
    }
    positions = std::move(flatPositions);
    normals = std::move(flatNormals);
    uvs = std::move(flatUvs);
}

uint64_t repairNormals(std::vector<glm::vec3>& normals, std::span<const glm::vec3> positions,
                       std::span<const uint32_t> indices) {
    std::vector<bool> bad(normals.size(), false);
    uint64_t badCount = 0;
    for (size_t i = 0; i < normals.size(); ++i) {
        if (usable(normals[i])) {
            normals[i] = glm::normalize(normals[i]);
        } else {
            bad[i] = true;
            ++badCount;
        }
    }
    if (badCount == 0) {
        return 0;
    }
    std::vector<glm::dvec3> sums(normals.size(), glm::dvec3(0.0));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::dvec3 n =
            areaNormal(positions[indices[t]], positions[indices[t + 1]], positions[indices[t + 2]]);
        for (size_t k = 0; k < 3; ++k) {
            if (bad[indices[t + k]]) {
                sums[indices[t + k]] += n;
            }
        }
    }
    for (size_t i = 0; i < normals.size(); ++i) {
        if (bad[i]) {
            const double length = glm::length(sums[i]);
            // A vertex no triangle uses (or whose faces cancel) keeps an arbitrary unit normal.
            normals[i] = length > 0.0 ? glm::vec3(sums[i] / length) : glm::vec3(0.0f, 0.0f, 1.0f);
        }
    }
    return badCount;
}

Bounds computeBounds(std::span<const glm::vec3> positions) {
    Bounds bounds;
    for (const glm::vec3& p : positions) {
        bounds.extend(p);
    }
    return bounds;
}

} // namespace lumina::scene
