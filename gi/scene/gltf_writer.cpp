#include "gi/scene/gltf_writer.h"

#include "gi/scene/mesh_repair.h"
#include "gi/scene/units.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

namespace lumina::scene {

namespace {

using Json = nlohmann::ordered_json;

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

// The shortest decimal that reads back as the same float, so files say 0.725, not
// 0.72500002384185791.
double shortest(float value) {
    if (value == 0.0f) {
        return 0.0; // not -0.0
    }
    char text[32];
    const auto result = std::to_chars(text, text + sizeof(text), value);
    double out = 0.0;
    std::from_chars(text, result.ptr, out);
    return out;
}

template <int N>
Json vec(const glm::vec<N, float>& v) {
    Json out = Json::array();
    for (int i = 0; i < N; ++i) {
        out.push_back(shortest(v[i]));
    }
    return out;
}

std::string base64(const std::vector<uint8_t>& bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t(bytes[i]) << 16 |
                           (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) |
                           (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0);
        out += kAlphabet[(n >> 18) & 63];
        out += kAlphabet[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
    }
    return out;
}

// Appends data to the one buffer and returns a bufferView + accessor for it.
class BufferWriter {
public:
    explicit BufferWriter(Json& root) : root_(root) {}

    template <typename T>
    int accessor(const std::vector<T>& values, int componentType, const char* type, size_t components,
                 int target, const Json& min = nullptr, const Json& max = nullptr) {
        while (bytes_.size() % 4 != 0) {
            bytes_.push_back(0);
        }
        const size_t offset = bytes_.size();
        const size_t size = values.size() * sizeof(T);
        bytes_.resize(offset + size);
        std::memcpy(bytes_.data() + offset, values.data(), size);
        root_["bufferViews"].push_back(
            Json{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
        Json accessor{{"bufferView", root_["bufferViews"].size() - 1},
                      {"componentType", componentType},
                      {"count", values.size() * sizeof(T) / (sizeof(float) * components)},
                      {"type", type}};
        if (!min.is_null()) {
            accessor["min"] = min;
            accessor["max"] = max;
        }
        root_["accessors"].push_back(accessor);
        return int(root_["accessors"].size() - 1);
    }

    void finish() {
        root_["buffers"] =
            Json::array({Json{{"byteLength", bytes_.size()},
                              {"uri", "data:application/octet-stream;base64," + base64(bytes_)}}});
    }

private:
    Json& root_;
    std::vector<uint8_t> bytes_;
};

// One primitive per submesh, each with the vertices its indices span, so that a loader
// concatenating primitives (as gltf_meshes.cpp does) gets the mesh's arrays back.
Json meshJson(const Mesh& mesh, BufferWriter& buffer) {
    Json primitives = Json::array();
    for (const Submesh& submesh : mesh.submeshes) {
        const auto first = mesh.indices.begin() + submesh.firstIndex;
        const auto last = first + submesh.indexCount;
        const uint32_t lo = *std::min_element(first, last), hi = *std::max_element(first, last);
        auto slice = [&](const auto& values) {
            return std::vector<typename std::decay_t<decltype(values)>::value_type>(values.begin() + lo,
                                                                                    values.begin() + hi + 1);
        };
        const std::vector<glm::vec3> positions = slice(mesh.positions);
        std::vector<uint32_t> indices(first, last);
        for (uint32_t& index : indices) {
            index -= lo;
        }
        const Bounds bounds = computeBounds(positions);
        const Json attributes{
            {"POSITION",
             buffer.accessor(positions, kFloat, "VEC3", 3, kArrayBuffer, vec(bounds.min), vec(bounds.max))},
            {"NORMAL", buffer.accessor(slice(mesh.normals), kFloat, "VEC3", 3, kArrayBuffer)},
            {"TEXCOORD_0", buffer.accessor(slice(mesh.uvs), kFloat, "VEC2", 2, kArrayBuffer)}};
        primitives.push_back(
            Json{{"attributes", attributes},
                 {"indices", buffer.accessor(indices, kUnsignedInt, "SCALAR", 1, kElementArrayBuffer)},
                 {"material", submesh.material}});
    }
    return Json{{"name", mesh.name}, {"primitives", primitives}};
}

Json materialJson(const Material& material) {
    Json out{{"name", material.name},
             {"pbrMetallicRoughness",
              {{"baseColorFactor", vec(material.baseColor)},
               {"metallicFactor", shortest(material.metallic)},
               {"roughnessFactor", shortest(material.roughness)}}}};
    // glTF keeps emissiveFactor in [0, 1]; the rest goes in KHR_materials_emissive_strength.
    const float strength = std::max({material.emission.x, material.emission.y, material.emission.z});
    if (strength > 0.0f) {
        out["emissiveFactor"] = vec(strength > 1.0f ? material.emission / strength : material.emission);
        if (strength > 1.0f) {
            out["extensions"] = {
                {"KHR_materials_emissive_strength", {{"emissiveStrength", shortest(strength)}}}};
        }
    }
    if (material.doubleSided) {
        out["doubleSided"] = true;
    }
    return out;
}

// The rotation taking glTF's local frame (looking down -z, +y up) to `forward` and `up`.
Json orientation(const glm::vec3& forward, const glm::vec3& up) {
    const glm::vec3 f = glm::normalize(forward);
    const glm::vec3 r = glm::normalize(glm::cross(f, up));
    const glm::vec3 u = glm::cross(r, f);
    const glm::quat q = glm::normalize(glm::quat_cast(glm::mat3(r, u, -f)));
    return Json::array({shortest(q.x), shortest(q.y), shortest(q.z), shortest(q.w)});
}

// Any unit vector not parallel to `v`.
glm::vec3 perpendicularUp(const glm::vec3& v) {
    return std::abs(v.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
}

Json lightJson(const Light& light, double metresPerUnit) {
    const double intensity = light.type == LightType::Directional
                                 ? double(light.intensity)
                                 : candelaFromPointIntensity(light.intensity, metresPerUnit);
    Json out{{"name", light.name},
             {"type", lightTypeName(light.type)},
             {"color", vec(light.color)},
             {"intensity", intensity}};
    if (light.range > 0.0f) {
        out["range"] = shortest(light.range);
    }
    if (light.type == LightType::Spot) {
        out["spot"] = {{"innerConeAngle", shortest(light.innerConeAngle)},
                       {"outerConeAngle", shortest(light.outerConeAngle)}};
    }
    return out;
}

bool isIdentity(const glm::mat4& m) {
    return m == glm::mat4(1.0f);
}

} // namespace

std::string writeGltf(const Scene& scene) {
    Json root;
    root["asset"] = {{"version", "2.0"},
                     {"generator", "Lumina built-in scene generator (gi/scene/generators)"}};
    std::vector<std::string> extensions;
    for (const Material& material : scene.materials) {
        if (std::max({material.emission.x, material.emission.y, material.emission.z}) > 1.0f) {
            extensions.push_back("KHR_materials_emissive_strength");
            break;
        }
    }
    if (!scene.lights.empty()) {
        extensions.push_back("KHR_lights_punctual");
    }
    if (!extensions.empty()) {
        root["extensionsUsed"] = extensions;
    }
    root["scene"] = 0;
    root["scenes"] = Json::array({Json{{"nodes", Json::array()}}});
    root["nodes"] = Json::array();
    root["meshes"] = Json::array();
    root["materials"] = Json::array();
    root["accessors"] = Json::array();
    root["bufferViews"] = Json::array();
    BufferWriter buffer(root);
    auto addNode = [&](Json node) {
        root["scenes"][0]["nodes"].push_back(root["nodes"].size());
        root["nodes"].push_back(std::move(node));
    };
    for (const Mesh& mesh : scene.meshes) {
        root["meshes"].push_back(meshJson(mesh, buffer));
    }
    for (const Material& material : scene.materials) {
        root["materials"].push_back(materialJson(material));
    }
    for (const Instance& instance : scene.instances) {
        Json node{{"name", instance.name}, {"mesh", instance.mesh}};
        if (!isIdentity(instance.transform)) {
            Json matrix = Json::array();
            for (int c = 0; c < 4; ++c) {
                for (int r = 0; r < 4; ++r) {
                    matrix.push_back(shortest(instance.transform[c][r]));
                }
            }
            node["matrix"] = matrix;
        }
        addNode(std::move(node));
    }
    if (!scene.lights.empty()) {
        Json lights = Json::array();
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            const Light& light = scene.lights[i];
            lights.push_back(lightJson(light, scene.units.metresPerUnit));
            Json node{{"name", light.name}};
            if (light.type != LightType::Directional) {
                node["translation"] = vec(light.position);
            }
            if (light.type != LightType::Point) {
                node["rotation"] = orientation(light.direction, perpendicularUp(light.direction));
            }
            node["extensions"] = {{"KHR_lights_punctual", {{"light", i}}}};
            addNode(std::move(node));
        }
        root["extensions"] = {{"KHR_lights_punctual", {{"lights", lights}}}};
    }
    if (scene.cameraFromFile) {
        const Camera& camera = scene.camera;
        root["cameras"] = Json::array({Json{{"name", camera.name},
                                            {"type", "perspective"},
                                            {"perspective",
                                             {{"aspectRatio", shortest(scene.aspect())},
                                              {"yfov", shortest(camera.fovY)},
                                              {"znear", shortest(camera.nearPlane)},
                                              {"zfar", shortest(camera.farPlane)}}}}});
        addNode(Json{{"name", camera.name},
                     {"camera", 0},
                     {"translation", vec(camera.position)},
                     {"rotation", orientation(camera.forward, camera.up)}});
    }
    buffer.finish();
    return root.dump(1) + "\n";
}

std::string writeSceneFile(const Scene& scene, const std::string& gltfFileName) {
    Json root;
    root["description"] = scene.description;
    root["gltf"] = gltfFileName;
    root["metresPerUnit"] = scene.units.metresPerUnit;
    root["sky"] = vec(scene.sky);
    root["image"] = {{"width", scene.image.width}, {"height", scene.image.height}};
    if (!scene.technique.empty()) {
        root["technique"] = scene.technique;
    }
    if (!scene.preset.empty()) {
        root["preset"] = scene.preset;
    }
    return root.dump(2) + "\n";
}

} // namespace lumina::scene
