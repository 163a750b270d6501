// The node hierarchy: world transforms, mesh instances, KHR_lights_punctual lights and the
// first perspective camera, walked from the default scene's roots (or from every root node
// when the file has no scenes).
#include "gi/scene/gltf_internal.h"
#include "gi/scene/units.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <numbers>

namespace lumina::scene::gltf {

namespace {

// Below this |determinant| the node's scale is taken as zero: its instance has no area.
constexpr double kZeroScaleDeterminant = 1e-18;

bool finite(const std::vector<double>& values) {
    for (double v : values) {
        if (!std::isfinite(v)) {
            return false;
        }
    }
    return true;
}

glm::dmat4 localTransform(const Context& context, const tinygltf::Node& node, const std::string& what) {
    if (!finite(node.matrix) || !finite(node.translation) || !finite(node.rotation) || !finite(node.scale)) {
        context.fail(what + ": its transform has a non-finite value");
    }
    if (node.matrix.size() == 16) {
        return glm::make_mat4(node.matrix.data());
    }
    if (!node.matrix.empty()) {
        context.fail(what + ": matrix has " + std::to_string(node.matrix.size()) + " values, not 16");
    }
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) {
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    } else if (!node.translation.empty()) {
        context.fail(what + ": translation has " + std::to_string(node.translation.size()) +
                     " values, not 3");
    }
    if (node.rotation.size() == 4) {
        // glTF stores x, y, z, w; glm's constructor takes w first.
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        if (!(length > 1e-6)) {
            context.fail(what + ": rotation quaternion has zero length");
        }
        m *= glm::mat4_cast(q / length);
    } else if (!node.rotation.empty()) {
        context.fail(what + ": rotation has " + std::to_string(node.rotation.size()) + " values, not 4");
    }
    if (node.scale.size() == 3) {
        m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    } else if (!node.scale.empty()) {
        context.fail(what + ": scale has " + std::to_string(node.scale.size()) + " values, not 3");
    }
    return m;
}

float checkedNumber(const Context& context, double value, double min, double max, const std::string& what) {
    if (!std::isfinite(value) || value < min || value > max) {
        context.fail(what + " is " + std::to_string(value) + ", outside [" + std::to_string(min) + ", " +
                     std::to_string(max) + "]");
    }
    return float(value);
}

Light convertLight(const Context& context, size_t index, const glm::dmat4& world) {
    const tinygltf::Light& source = context.model.lights[index];
    const std::string what = describe("light", index, source.name);
    Light light;
    light.name = source.name.empty() ? "light " + std::to_string(index) : source.name;
    if (source.type == "directional") {
        light.type = LightType::Directional;
    } else if (source.type == "point") {
        light.type = LightType::Point;
    } else if (source.type == "spot") {
        light.type = LightType::Spot;
    } else {
        context.fail(what + ": unknown type '" + source.type + "' (directional, point or spot)");
    }
    if (!source.color.empty()) {
        if (source.color.size() != 3) {
            context.fail(what + ": color has " + std::to_string(source.color.size()) + " values, not 3");
        }
        for (int c = 0; c < 3; ++c) {
            light.color[c] = checkedNumber(context, source.color[size_t(c)], 0.0, 1e30, what + ": color");
        }
    }
    const double intensity = checkedNumber(context, source.intensity, 0.0, 1e30, what + ": intensity");
    light.intensity = light.type == LightType::Directional
                          ? float(intensity)
                          : float(pointIntensityFromCandela(intensity, context.options.metresPerUnit));
    const glm::vec3 strength = light.strength();
    if (!std::isfinite(light.intensity) || !std::isfinite(strength.x + strength.y + strength.z)) {
        context.fail(what + ": intensity " + std::to_string(intensity) + " overflows in scene units");
    }
    light.range = checkedNumber(context, source.range, 0.0, 1e30, what + ": range");
    if (light.type == LightType::Spot) {
        constexpr double kHalfPi = std::numbers::pi / 2.0;
        light.innerConeAngle =
            checkedNumber(context, source.spot.innerConeAngle, 0.0, kHalfPi, what + ": innerConeAngle");
        light.outerConeAngle =
            checkedNumber(context, source.spot.outerConeAngle, 0.0, kHalfPi, what + ": outerConeAngle");
        if (light.innerConeAngle >= light.outerConeAngle) {
            context.fail(what + ": innerConeAngle must be less than outerConeAngle");
        }
    }
    light.position = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 direction = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
    if (!(glm::length(direction) > 0.0)) {
        context.fail(what + ": its node's transform has zero scale, so the light has no direction");
    }
    light.direction = glm::vec3(glm::normalize(direction));
    return light;
}

void convertCamera(const Context& context, size_t index, const glm::dmat4& world, Scene& scene) {
    const tinygltf::Camera& source = context.model.cameras[index];
    const std::string what = describe("camera", index, source.name);
    if (source.type != "perspective") {
        context.warn(what + ": " + source.type + " cameras are not supported; ignored");
        return;
    }
    const tinygltf::PerspectiveCamera& p = source.perspective;
    Camera camera;
    camera.name = source.name.empty() ? "camera " + std::to_string(index) : source.name;
    camera.fovY = checkedNumber(context, p.yfov, 1e-4, std::numbers::pi - 1e-4, what + ": yfov");
    camera.nearPlane = checkedNumber(context, p.znear, 1e-30, 1e30, what + ": znear");
    camera.farPlane = p.zfar == 0.0 ? 0.0f : checkedNumber(context, p.zfar, p.znear, 1e30, what + ": zfar");
    const glm::dmat3 basis(world);
    const glm::dvec3 forward = basis * glm::dvec3(0.0, 0.0, -1.0);
    const glm::dvec3 up = basis * glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 right = glm::cross(forward, up);
    if (!(glm::length(right) > 0.0)) {
        context.fail(what + ": its node's transform is degenerate (zero scale?)");
    }
    camera.position = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    camera.forward = glm::vec3(glm::normalize(forward));
    camera.up = glm::vec3(glm::normalize(glm::cross(glm::normalize(right), glm::normalize(forward))));
    scene.camera = camera;
    scene.cameraFromFile = true;
    if (p.aspectRatio > 0.0 && std::isfinite(p.aspectRatio)) {
        const double height = std::round(double(scene.image.width) / p.aspectRatio);
        scene.image.height = uint32_t(std::clamp(height, 1.0, 16384.0));
    }
}

// The nodes to start from, after checking that the hierarchy is a set of trees (glTF 2.0,
// 3.5.3: "the node hierarchy MUST be a set of disjoint strict trees").
std::vector<int> rootNodes(const Context& context) {
    const tinygltf::Model& model = context.model;
    std::vector<int> parent(model.nodes.size(), -1);
    for (size_t i = 0; i < model.nodes.size(); ++i) {
        for (int child : model.nodes[i].children) {
            if (child < 0 || size_t(child) >= model.nodes.size()) {
                context.fail(describe("node", i, model.nodes[i].name) + ": child " + std::to_string(child) +
                             " does not exist");
            }
            if (parent[size_t(child)] != -1 || size_t(child) == i) {
                context.fail("the node hierarchy is not a tree: node " + std::to_string(child) +
                             " has more than one parent (or is its own ancestor)");
            }
            parent[size_t(child)] = int(i);
        }
    }
    std::vector<int> roots;
    if (model.scenes.empty()) {
        if (!model.nodes.empty()) {
            context.warn("no scenes: every root node is drawn");
        }
        for (size_t i = 0; i < model.nodes.size(); ++i) {
            if (parent[i] == -1) {
                roots.push_back(int(i));
            }
        }
        return roots;
    }
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(sceneIndex) >= model.scenes.size()) {
        context.fail("default scene " + std::to_string(sceneIndex) + " does not exist");
    }
    std::vector<bool> seen(model.nodes.size(), false);
    for (int root : model.scenes[size_t(sceneIndex)].nodes) {
        if (root < 0 || size_t(root) >= model.nodes.size()) {
            context.fail("scene " + std::to_string(sceneIndex) + ": node " + std::to_string(root) +
                         " does not exist");
        }
        if (seen[size_t(root)]) {
            context.fail("scene " + std::to_string(sceneIndex) + " lists root node " + std::to_string(root) +
                         " twice");
        }
        if (parent[size_t(root)] != -1) {
            context.fail("the node hierarchy is not a tree: scene " + std::to_string(sceneIndex) +
                         " root node " + std::to_string(root) + " is also a child of node " +
                         std::to_string(parent[size_t(root)]) + " (a cycle?)");
        }
        seen[size_t(root)] = true;
        roots.push_back(root);
    }
    return roots;
}

} // namespace

NodeOrigins convertNodes(const Context& context, const std::vector<int64_t>& meshIndex, Scene& scene) {
    const tinygltf::Model& model = context.model;
    NodeOrigins origins;
    struct Pending {
        int node;
        glm::dmat4 parentWorld;
    };
    std::vector<Pending> stack;
    const std::vector<int> roots = rootNodes(context);
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
        stack.push_back({*it, glm::dmat4(1.0)});
    }
    bool warnedSkin = false;
    while (!stack.empty()) {
        const Pending pending = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = model.nodes[size_t(pending.node)];
        const std::string what = describe("node", size_t(pending.node), node.name);
        const glm::dmat4 world = pending.parentWorld * localTransform(context, node, what);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) {
                if (!std::isfinite(world[c][r]) || std::abs(world[c][r]) > 1e30) {
                    context.fail(what + ": its world transform overflows (huge scale?)");
                }
            }
        }
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
            stack.push_back({*child, world});
        }
        if (node.skin >= 0 && !warnedSkin) {
            context.warn(what + ": skins ignored (meshes are drawn in their bind pose)");
            warnedSkin = true;
        }
        if (node.camera >= 0) {
            if (size_t(node.camera) >= model.cameras.size()) {
                context.fail(what + ": camera " + std::to_string(node.camera) + " does not exist");
            }
            if (!scene.cameraFromFile) {
                convertCamera(context, size_t(node.camera), world, scene);
            }
        }
        if (const auto light = node.extensions.find("KHR_lights_punctual"); light != node.extensions.end()) {
            const tinygltf::Value& reference = light->second;
            const tinygltf::Value& index = reference.IsObject() ? reference.Get("light") : tinygltf::Value();
            if (!index.IsInt() || index.GetNumberAsInt() < 0 ||
                size_t(index.GetNumberAsInt()) >= model.lights.size()) {
                context.fail(what + ": KHR_lights_punctual names a light that does not exist");
            }
            scene.lights.push_back(convertLight(context, size_t(index.GetNumberAsInt()), world));
            origins.lightNode.push_back(pending.node);
        }
        if (node.mesh < 0) {
            continue;
        }
        if (size_t(node.mesh) >= model.meshes.size()) {
            context.fail(what + ": mesh " + std::to_string(node.mesh) + " does not exist");
        }
        if (meshIndex[size_t(node.mesh)] < 0) {
            continue; // no triangles
        }
        if (std::abs(glm::determinant(glm::dmat3(world))) < kZeroScaleDeterminant) {
            context.warn(what + ": zero scale; its instance is dropped");
            continue;
        }
        Instance instance;
        instance.mesh = uint32_t(meshIndex[size_t(node.mesh)]);
        instance.transform = glm::mat4(world);
        instance.name = node.name.empty() ? "node " + std::to_string(pending.node) : node.name;
        const Bounds bounds = transformBounds(scene.meshes[instance.mesh].bounds, instance.transform);
        const float reach = std::max(glm::length(bounds.min), glm::length(bounds.max));
        if (!std::isfinite(reach) || reach > kMaxCoordinate) {
            context.fail(what + ": its mesh reaches " + std::to_string(reach) +
                         " scene units from the origin, beyond the supported 1e8 (huge scale?)");
        }
        if (scene.instances.size() >= kMaxInstances) {
            context.fail("more than " + std::to_string(kMaxInstances) + " mesh instances");
        }
        scene.instances.push_back(std::move(instance));
        origins.instanceNode.push_back(pending.node);
    }
    return origins;
}

} // namespace lumina::scene::gltf
