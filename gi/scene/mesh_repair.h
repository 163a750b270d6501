#pragma once
// Geometry repairs the loader applies (docs/scenes.md, "Bad input"), and normal generation.
#include "gi/scene/scene.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lumina::scene {

// A triangle is degenerate when twice its area is below this fraction of its longest edge
// squared: what float rounding leaves of three collinear or coincident points.
inline constexpr double kDegenerateRelativeArea = 1e-7;

bool isDegenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// Removes degenerate triangles from a triangle list; returns how many it removed.
uint64_t dropDegenerateTriangles(std::vector<uint32_t>& indices, std::span<const glm::vec3> positions);

// Gives every triangle its own three vertices carrying its face normal: glTF's rule for
// primitives without normals ("flat normals"). uvs may be empty.
void makeFlatShaded(std::vector<glm::vec3>& positions, std::vector<glm::vec2>& uvs,
                    std::vector<glm::vec3>& normals, std::vector<uint32_t>& indices);

// Normalises `normals`; one that is not finite or has zero length is replaced by the
// area-weighted mean of the face normals around its vertex. Returns how many were replaced.
uint64_t repairNormals(std::vector<glm::vec3>& normals, std::span<const glm::vec3> positions,
                       std::span<const uint32_t> indices);

Bounds computeBounds(std::span<const glm::vec3> positions);

} // namespace lumina::scene
