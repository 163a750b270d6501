#pragma once
// Small procedural meshes for the BVH and SDF tests and benchmarks. Closed meshes share
// bit-identical vertices (indexed, one position per lattice point) and wind counter-
// clockwise seen from outside, so cross(v1 - v0, v2 - v0) points out.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <map>
#include <random>
#include <tuple>
#include <vector>

namespace lumina::test {

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    size_t triangleCount() const { return indices.size() / 3; }
    void append(const Mesh& other) {
        const uint32_t base = uint32_t(positions.size());
        positions.insert(positions.end(), other.positions.begin(), other.positions.end());
        for (uint32_t i : other.indices) {
            indices.push_back(base + i);
        }
    }
};

// An axis-aligned box, each face split into n x n quads (two triangles each). Faces listed
// in `skipFaces` (0..5 = -x, +x, -y, +y, -z, +z) are left out, which makes open boxes.
inline Mesh makeBox(glm::vec3 lo, glm::vec3 hi, int n = 1, std::vector<int> skipFaces = {}) {
    Mesh mesh;
    std::map<std::tuple<int, int, int>, uint32_t> lattice;
    auto vertex = [&](int i, int j, int k) {
        auto [it, inserted] = lattice.try_emplace({i, j, k}, uint32_t(mesh.positions.size()));
        if (inserted) {
            const glm::vec3 f = glm::vec3(float(i), float(j), float(k)) / float(n);
            mesh.positions.push_back(lo + (hi - lo) * f);
        }
        return it->second;
    };
    for (int face = 0; face < 6; ++face) {
        if (std::find(skipFaces.begin(), skipFaces.end(), face) != skipFaces.end()) {
            continue;
        }
        const int axis = face / 2;
        const bool positive = face % 2 == 1;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int a = 0; a < n; ++a) {
            for (int b = 0; b < n; ++b) {
                uint32_t q[4];
                const int corners[4][2] = {{a, b}, {a + 1, b}, {a + 1, b + 1}, {a, b + 1}};
                for (int c = 0; c < 4; ++c) {
                    int ijk[3];
                    ijk[axis] = positive ? n : 0;
                    ijk[u] = corners[c][0];
                    ijk[v] = corners[c][1];
                    q[c] = vertex(ijk[0], ijk[1], ijk[2]);
                }
                // (u, v, axis) is right-handed, so u x v = +axis: CCW in (u, v) faces +axis.
                if (positive) {
                    mesh.indices.insert(mesh.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
                } else {
                    mesh.indices.insert(mesh.indices.end(), {q[0], q[2], q[1], q[0], q[3], q[2]});
                }
            }
        }
    }
    return mesh;
}

// A subdivided icosahedron pushed onto the sphere (20 * 4^subdivisions triangles).
inline Mesh makeIcosphere(glm::vec3 centre, float radius, int subdivisions) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> dirs = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (glm::vec3& d : dirs) {
        d = glm::normalize(d);
    }
    std::vector<uint32_t> tris = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                  4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                  6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto mid = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto [it, inserted] = midpoints.try_emplace({key.first, key.second}, uint32_t(dirs.size()));
            if (inserted) {
                dirs.push_back(glm::normalize(dirs[key.first] + dirs[key.second]));
            }
            return it->second;
        };
        std::vector<uint32_t> next;
        for (size_t i = 0; i < tris.size(); i += 3) {
            const uint32_t a = tris[i], b = tris[i + 1], c = tris[i + 2];
            const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        tris = std::move(next);
    }
    Mesh mesh;
    for (const glm::vec3& d : dirs) {
        mesh.positions.push_back(centre + radius * d);
    }
    mesh.indices = std::move(tris);
    return mesh;
}

// A flat n x n grid of quads in the xz plane at height y, facing +y.
inline Mesh makeGrid(glm::vec2 lo, glm::vec2 hi, float y, int n) {
    Mesh mesh;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const glm::vec2 f = glm::vec2(float(i), float(j)) / float(n);
            const glm::vec2 p = lo + (hi - lo) * f;
            mesh.positions.push_back({p.x, y, p.y});
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, d, a, d, b});
        }
    }
    return mesh;
}

// Unconnected triangles of edge length up to `size`, centred in [-extent, extent]^3.
inline Mesh makeRandomTriangles(uint32_t count, uint32_t seed, float extent = 10.0f, float size = 1.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-extent, extent), off(-size, size);
    Mesh mesh;
    for (uint32_t t = 0; t < count; ++t) {
        const glm::vec3 c(pos(rng), pos(rng), pos(rng));
        for (int k = 0; k < 3; ++k) {
            mesh.indices.push_back(uint32_t(mesh.positions.size()));
            mesh.positions.push_back(c + glm::vec3(off(rng), off(rng), off(rng)));
        }
    }
    return mesh;
}

inline glm::vec3 randomUnitVector(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    for (;;) {
        const glm::vec3 v(n(rng), n(rng), n(rng));
        const float len = glm::length(v);
        if (len > 1e-6f) {
            return v / len;
        }
    }
}

} // namespace lumina::test
