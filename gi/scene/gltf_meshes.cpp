// glTF meshes to scene meshes: each glTF mesh becomes one Mesh whose primitives are
// submeshes. Strips and fans become lists; points and lines are skipped; degenerate
// triangles are dropped; missing normals are generated flat, bad ones repaired.
#include "gi/scene/gltf_accessor.h"
#include "gi/scene/gltf_internal.h"
#include "gi/scene/mesh_repair.h"

#include <cmath>
#include <optional>

namespace lumina::scene::gltf {

namespace {

struct Geometry {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;
};

template <typename Vec>
std::vector<Vec> toVectors(const std::vector<float>& floats) {
    constexpr size_t n = sizeof(Vec) / sizeof(float);
    std::vector<Vec> out(floats.size() / n);
    for (size_t i = 0; i < out.size(); ++i) {
        for (size_t c = 0; c < n; ++c) {
            out[i][int(c)] = floats[i * n + c];
        }
    }
    return out;
}

const char* modeName(int mode) {
    switch (mode) {
    case TINYGLTF_MODE_POINTS:
        return "points";
    case TINYGLTF_MODE_LINE:
        return "lines";
    case TINYGLTF_MODE_LINE_LOOP:
        return "line loop";
    default:
        return "line strip";
    }
}

// Triangle strips and fans as triangle lists, glTF's vertex order (spec 3.7.2.1).
std::vector<uint32_t> toTriangleList(const Context& context, std::vector<uint32_t> indices, int mode,
                                     const std::string& what) {
    std::vector<uint32_t> list;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (indices.size() % 3 != 0) {
            context.warn(what + ": " + std::to_string(indices.size()) +
                         " vertices is not a whole number of triangles; the last " +
                         std::to_string(indices.size() % 3) + " are ignored");
            indices.resize(indices.size() - indices.size() % 3);
        }
        return indices;
    }
    const size_t triangles = indices.size() >= 3 ? indices.size() - 2 : 0;
    list.reserve(triangles * 3);
    for (size_t i = 0; i < triangles; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            list.insert(list.end(), {indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]});
        } else {
            list.insert(list.end(), {indices[i + 1], indices[i + 2], indices[0]});
        }
    }
    return list;
}

std::optional<Geometry> readPrimitive(const Context& context, const tinygltf::Primitive& primitive,
                                      const std::string& what) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
        context.warn(what + ": " + modeName(mode) + " skipped (only triangles are drawn)");
        ++context.report.nonTrianglePrimitivesSkipped;
        return std::nullopt;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        context.fail(what + ": unknown primitive mode " + std::to_string(mode));
    }
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
        context.fail(what + ": has no POSITION attribute");
    }
    Geometry g;
    g.positions = toVectors<glm::vec3>(readFloatAccessor(context, position->second, 3, what + " POSITION"));
    for (size_t i = 0; i < g.positions.size(); ++i) {
        const glm::vec3& p = g.positions[i];
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(p[c]) || std::abs(p[c]) > kMaxCoordinate) {
                context.fail(
                    what + ": POSITION " + std::to_string(i) + " is (" + std::to_string(p.x) + ", " +
                    std::to_string(p.y) + ", " + std::to_string(p.z) + ")" +
                    (std::isfinite(p[c]) ? ", beyond the supported 1e8 scene units" : ", not finite"));
            }
        }
    }
    const size_t vertexCount = g.positions.size();

    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
        indices = readIndexAccessor(context, primitive.indices, what + " indices");
        for (size_t i = 0; i < indices.size(); ++i) {
            if (indices[i] >= vertexCount) {
                context.fail(what + ": index " + std::to_string(i) + " is " + std::to_string(indices[i]) +
                             ", out of range for " + std::to_string(vertexCount) + " vertices");
            }
        }
    } else {
        indices.resize(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i) {
            indices[i] = uint32_t(i);
        }
    }
    g.indices = toTriangleList(context, std::move(indices), mode, what);

    if (primitive.attributes.contains("COLOR_0")) {
        context.warn(what + ": COLOR_0 ignored (vertex colours are not drawn)");
    }
    const auto texcoord = primitive.attributes.find("TEXCOORD_0");
    if (texcoord != primitive.attributes.end()) {
        g.uvs = toVectors<glm::vec2>(readFloatAccessor(context, texcoord->second, 2, what + " TEXCOORD_0"));
        if (g.uvs.size() != vertexCount) {
            context.fail(what + ": TEXCOORD_0 has " + std::to_string(g.uvs.size()) +
                         " elements, POSITION has " + std::to_string(vertexCount));
        }
        size_t bad = 0;
        for (glm::vec2& uv : g.uvs) {
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
                uv = glm::vec2(0.0f);
                ++bad;
            }
        }
        if (bad != 0) {
            context.warn(what + ": " + std::to_string(bad) + " non-finite TEXCOORD_0 values set to 0");
        }
    }

    const uint64_t dropped = dropDegenerateTriangles(g.indices, g.positions);
    if (dropped != 0) {
        context.report.degenerateTrianglesDropped += dropped;
        context.warn(what + ": " + std::to_string(dropped) + " degenerate triangle(s) dropped");
    }

    const auto normal = primitive.attributes.find("NORMAL");
    if (normal == primitive.attributes.end()) {
        makeFlatShaded(g.positions, g.uvs, g.normals, g.indices);
    } else {
        g.normals = toVectors<glm::vec3>(readFloatAccessor(context, normal->second, 3, what + " NORMAL"));
        if (g.normals.size() != vertexCount) {
            context.fail(what + ": NORMAL has " + std::to_string(g.normals.size()) +
                         " elements, POSITION has " + std::to_string(vertexCount));
        }
        const uint64_t repaired = repairNormals(g.normals, g.positions, g.indices);
        if (repaired != 0) {
            context.report.normalsRepaired += repaired;
            context.warn(what + ": " + std::to_string(repaired) +
                         " zero-length or non-finite normal(s) regenerated from the faces");
        }
    }
    if (g.uvs.empty()) {
        g.uvs.assign(g.positions.size(), glm::vec2(0.0f));
    }
    return g;
}

} // namespace

std::vector<int64_t> convertMeshes(const Context& context, Scene& scene, uint32_t defaultMaterial) {
    const tinygltf::Model& model = context.model;
    std::vector<int64_t> meshIndex(model.meshes.size(), -1);
    uint64_t vertexTotal = 0;
    for (size_t m = 0; m < model.meshes.size(); ++m) {
        const tinygltf::Mesh& source = model.meshes[m];
        Mesh mesh;
        mesh.name = source.name.empty() ? "mesh " + std::to_string(m) : source.name;
        if (!source.weights.empty()) {
            context.warn(describe("mesh", m, source.name) +
                         ": morph targets ignored (the base shape is drawn)");
        }
        for (size_t p = 0; p < source.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = source.primitives[p];
            const std::string what = describe("mesh", m, source.name) + " primitive " + std::to_string(p);
            std::optional<Geometry> g = readPrimitive(context, primitive, what);
            if (!g || g->indices.empty()) {
                continue;
            }
            uint32_t material = defaultMaterial;
            if (primitive.material >= 0) {
                if (size_t(primitive.material) >= model.materials.size()) {
                    context.fail(what + ": material " + std::to_string(primitive.material) +
                                 " does not exist");
                }
                material = uint32_t(primitive.material);
            } else if (primitive.material != -1) {
                context.fail(what + ": material " + std::to_string(primitive.material) + " does not exist");
            }
            const uint64_t base = mesh.positions.size();
            vertexTotal += g->positions.size();
            if (vertexTotal > context.options.maxVertices) {
                context.fail("more than " + std::to_string(context.options.maxVertices) + " vertices in all");
            }
            if (base + g->positions.size() > kMaxMeshVertices) {
                context.fail(describe("mesh", m, source.name) + ": more than " +
                             std::to_string(kMaxMeshVertices) + " vertices");
            }
            mesh.submeshes.push_back({uint32_t(mesh.indices.size()), uint32_t(g->indices.size()), material});
            for (uint32_t index : g->indices) {
                mesh.indices.push_back(uint32_t(base + index));
            }
            mesh.positions.insert(mesh.positions.end(), g->positions.begin(), g->positions.end());
            mesh.normals.insert(mesh.normals.end(), g->normals.begin(), g->normals.end());
            mesh.uvs.insert(mesh.uvs.end(), g->uvs.begin(), g->uvs.end());
        }
        if (mesh.submeshes.empty()) {
            continue;
        }
        mesh.bounds = computeBounds(mesh.positions);
        meshIndex[m] = int64_t(scene.meshes.size());
        scene.meshes.push_back(std::move(mesh));
    }
    return meshIndex;
}

} // namespace lumina::scene::gltf
