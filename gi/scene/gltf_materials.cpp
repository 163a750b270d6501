// glTF materials to scene materials: base colour, emission (factor x
// KHR_materials_emissive_strength), metallic, roughness, double-sidedness.
#include "gi/scene/gltf_internal.h"

#include <cmath>

namespace lumina::scene::gltf {

namespace {

// Larger factors would overflow float radiance once multiplied by a strength.
constexpr double kMaxFactor = 1e30;

// factor[i] for i < N, checked finite and non-negative, `fallback` when absent.
template <int N>
glm::vec<N, float> readFactor(const Context& context, const std::vector<double>& factor,
                              glm::vec<N, float> fallback, const std::string& what) {
    if (factor.empty()) {
        return fallback;
    }
    if (factor.size() != size_t(N)) {
        context.fail(what + " has " + std::to_string(factor.size()) + " components, not " +
                     std::to_string(N));
    }
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i) {
        if (!std::isfinite(factor[size_t(i)]) || factor[size_t(i)] < 0.0 || factor[size_t(i)] > kMaxFactor) {
            context.fail(what + " component " + std::to_string(i) + " is " +
                         std::to_string(factor[size_t(i)]) + " (must be in [0, 1e30])");
        }
        out[i] = float(factor[size_t(i)]);
    }
    return out;
}

float emissiveStrength(const Context& context, const tinygltf::Material& material, const std::string& what) {
    const auto it = material.extensions.find("KHR_materials_emissive_strength");
    if (it == material.extensions.end()) {
        return 1.0f;
    }
    const tinygltf::Value& extension = it->second;
    if (!extension.IsObject() || !extension.Has("emissiveStrength")) {
        return 1.0f;
    }
    const tinygltf::Value& strength = extension.Get("emissiveStrength");
    const double value = strength.IsNumber() ? strength.GetNumberAsDouble() : -1.0;
    if (!std::isfinite(value) || value < 0.0 || value > kMaxFactor) {
        context.fail(what + ": KHR_materials_emissive_strength.emissiveStrength must be in [0, 1e30]");
    }
    return float(value);
}

float unitFactor(const Context& context, double value, const std::string& what) {
    if (!std::isfinite(value) || value < 0.0 || value > 1.0) {
        context.fail(what + " is " + std::to_string(value) + " (must be in [0, 1])");
    }
    return float(value);
}

} // namespace

std::string describe(const char* kind, size_t index, const std::string& name) {
    return std::string(kind) + " " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

void convertMaterials(const Context& context, Scene& scene) {
    const tinygltf::Model& model = context.model;
    std::vector<int64_t> imageTexture(model.images.size(), -1);
    for (size_t m = 0; m < model.materials.size(); ++m) {
        const tinygltf::Material& source = model.materials[m];
        const std::string what = describe("material", m, source.name);
        const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
        Material out;
        out.name = source.name.empty() ? "material " + std::to_string(m) : source.name;
        out.baseColor =
            readFactor<4>(context, pbr.baseColorFactor, glm::vec4(1.0f), what + ": baseColorFactor");
        out.emission =
            readFactor<3>(context, source.emissiveFactor, glm::vec3(0.0f), what + ": emissiveFactor") *
            emissiveStrength(context, source, what);
        if (!std::isfinite(out.emission.x + out.emission.y + out.emission.z)) {
            context.fail(what + ": emissiveFactor x emissiveStrength overflows");
        }
        out.metallic = unitFactor(context, pbr.metallicFactor, what + ": metallicFactor");
        out.roughness = unitFactor(context, pbr.roughnessFactor, what + ": roughnessFactor");
        out.doubleSided = source.doubleSided;
        if (pbr.baseColorTexture.index >= 0) {
            out.baseColorTexture = convertTexture(context, pbr.baseColorTexture.index, what + " base colour",
                                                  scene, imageTexture);
            if (pbr.baseColorTexture.texCoord != 0) {
                context.warn(what + ": base colour texture reads TEXCOORD_" +
                             std::to_string(pbr.baseColorTexture.texCoord) + "; TEXCOORD_0 is used");
            }
        }
        if (source.emissiveTexture.index >= 0) {
            out.emissionTexture = convertTexture(context, source.emissiveTexture.index, what + " emissive",
                                                 scene, imageTexture);
            if (source.emissiveTexture.texCoord != 0) {
                context.warn(what + ": emissive texture reads TEXCOORD_" +
                             std::to_string(source.emissiveTexture.texCoord) + "; TEXCOORD_0 is used");
            }
        }
        if (source.alphaMode != "OPAQUE") {
            context.warn(what + ": alphaMode " + source.alphaMode + " drawn as OPAQUE");
        }
        if (source.extensions.contains("KHR_materials_pbrSpecularGlossiness")) {
            context.warn(what +
                         ": KHR_materials_pbrSpecularGlossiness ignored (metallic-roughness factors used)");
        }
        scene.materials.push_back(std::move(out));
    }
}

} // namespace lumina::scene::gltf
