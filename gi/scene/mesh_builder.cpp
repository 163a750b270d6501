#include "gi/scene/mesh_builder.h"

#include "gi/scene/mesh_repair.h"

#include <numbers>

namespace lumina::scene {

MeshBuilder::MeshBuilder(std::string name) {
    mesh_.name = std::move(name);
}

void MeshBuilder::material(uint32_t material) {
    material_ = material;
}

uint32_t MeshBuilder::vertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv) {
    mesh_.positions.push_back(position);
    mesh_.normals.push_back(normal);
    mesh_.uvs.push_back(uv);
    return uint32_t(mesh_.positions.size() - 1);
}

void MeshBuilder::triangle(uint32_t a, uint32_t b, uint32_t c) {
    const auto first = uint32_t(mesh_.indices.size());
    if (mesh_.submeshes.empty() || mesh_.submeshes.back().material != material_) {
        mesh_.submeshes.push_back({first, 0, material_});
    }
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
    mesh_.submeshes.back().indexCount += 3;
}

void MeshBuilder::quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const uint32_t i0 = vertex(a, n, {0.0f, 0.0f});
    const uint32_t i1 = vertex(b, n, {1.0f, 0.0f});
    const uint32_t i2 = vertex(c, n, {1.0f, 1.0f});
    const uint32_t i3 = vertex(d, n, {0.0f, 1.0f});
    triangle(i0, i1, i2);
    triangle(i0, i2, i3);
}

void MeshBuilder::quadFacingAwayFrom(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                                     const glm::vec3& d, const glm::vec3& inside) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, (a + b + c + d) * 0.25f - inside) >= 0.0f) {
        quad(a, b, c, d);
    } else {
        quad(d, c, b, a);
    }
}

void MeshBuilder::box(const glm::vec3& lo, const glm::vec3& hi, bool inward, uint32_t skipFaces) {
    const glm::vec3 centre = (lo + hi) * 0.5f;
    auto corner = [&](int x, int y, int z) {
        return glm::vec3(x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z);
    };
    // Each face's four corners, counter-clockwise seen from outside.
    const int faces[6][4][3] = {
        {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}, // -x
        {{1, 0, 1}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}}, // +x
        {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, // -y
        {{0, 1, 1}, {1, 1, 1}, {1, 1, 0}, {0, 1, 0}}, // +y
        {{1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}}, // -z
        {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, // +z
    };
    for (uint32_t f = 0; f < 6; ++f) {
        if (skipFaces & (1u << f)) {
            continue;
        }
        const auto& q = faces[f];
        const glm::vec3 a = corner(q[0][0], q[0][1], q[0][2]), b = corner(q[1][0], q[1][1], q[1][2]),
                        c = corner(q[2][0], q[2][1], q[2][2]), d = corner(q[3][0], q[3][1], q[3][2]);
        if (inward) {
            quad(d, c, b, a);
        } else {
            quadFacingAwayFrom(a, b, c, d, centre);
        }
    }
}

void MeshBuilder::roomFace(const glm::vec3& min, const glm::vec3& max, const std::vector<float>& xs,
                           const std::vector<float>& zs, uint32_t face,
                           const std::function<bool(size_t, size_t)>& skip) {
    const glm::vec3 centre = (min + max) * 0.5f;
    // Front face into the room: away from the quad's mirror image through the room's centre.
    const auto inward = [&](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
        quadFacingAwayFrom(a, b, c, d, 0.5f * (a + b + c + d) - centre);
    };
    const uint32_t axis = face / 2;
    const float at = face % 2 == 0 ? min[axis] : max[axis];
    if (axis == 1) { // floor or ceiling: a cell per pair of cuts
        for (size_t i = 0; i + 1 < xs.size(); ++i) {
            for (size_t k = 0; k + 1 < zs.size(); ++k) {
                if (!skip || !skip(i, k)) {
                    inward({xs[i], at, zs[k]}, {xs[i + 1], at, zs[k]}, {xs[i + 1], at, zs[k + 1]},
                           {xs[i], at, zs[k + 1]});
                }
            }
        }
        return;
    }
    // A wall: a full-height piece per pair of cuts along it.
    const std::vector<float>& cuts = axis == 0 ? zs : xs;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const auto point = [&](float along, float y) {
            return axis == 0 ? glm::vec3(at, y, along) : glm::vec3(along, y, at);
        };
        inward(point(cuts[i], min.y), point(cuts[i + 1], min.y), point(cuts[i + 1], max.y),
               point(cuts[i], max.y));
    }
}

void MeshBuilder::cylinder(const glm::vec3& base, float radius, float height, uint32_t segments,
                           uint32_t rings) {
    const auto first = uint32_t(mesh_.positions.size());
    for (uint32_t r = 0; r <= rings; ++r) {
        const float t = float(r) / float(rings);
        for (uint32_t s = 0; s <= segments; ++s) {
            const float angle = 2.0f * std::numbers::pi_v<float> * float(s) / float(segments);
            const glm::vec3 n(std::cos(angle), 0.0f, -std::sin(angle));
            vertex(base + n * radius + glm::vec3(0.0f, t * height, 0.0f), n, {float(s) / float(segments), t});
        }
    }
    const uint32_t row = segments + 1;
    for (uint32_t r = 0; r < rings; ++r) {
        for (uint32_t s = 0; s < segments; ++s) {
            const uint32_t i0 = first + r * row + s, i1 = i0 + 1, i2 = i0 + row + 1, i3 = i0 + row;
            triangle(i0, i1, i2);
            triangle(i0, i2, i3);
        }
    }
}

void MeshBuilder::grid(const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v, uint32_t nu,
                       uint32_t nv, const std::function<glm::vec3(float, float)>& offset) {
    const auto first = uint32_t(mesh_.positions.size());
    auto point = [&](float s, float t) { return origin + s * u + t * v + offset(s, t); };
    const float ds = 0.5f / float(nu), dt = 0.5f / float(nv);
    for (uint32_t j = 0; j <= nv; ++j) {
        for (uint32_t i = 0; i <= nu; ++i) {
            const float s = float(i) / float(nu), t = float(j) / float(nv);
            // Central differences of the displaced surface give its normal.
            const glm::vec3 du = point(s + ds, t) - point(s - ds, t);
            const glm::vec3 dv = point(s, t + dt) - point(s, t - dt);
            vertex(point(s, t), glm::normalize(glm::cross(du, dv)), {s, t});
        }
    }
    const uint32_t row = nu + 1;
    for (uint32_t j = 0; j < nv; ++j) {
        for (uint32_t i = 0; i < nu; ++i) {
            const uint32_t i0 = first + j * row + i, i1 = i0 + 1, i2 = i0 + row + 1, i3 = i0 + row;
            triangle(i0, i1, i2);
            triangle(i0, i2, i3);
        }
    }
}

Mesh MeshBuilder::finish() {
    mesh_.bounds = computeBounds(mesh_.positions);
    return std::move(mesh_);
}

} // namespace lumina::scene
