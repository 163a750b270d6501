#include "gi/scene/scene_animation.h"

#include "gi/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace lumina::scene {

namespace {

// `time` folded into [0, length): where a track that loops every `length` seconds is.
double loopTime(double time, double length) {
    if (!(length > 0.0)) {
        return 0.0;
    }
    const double folded = time - std::floor(time / length) * length;
    return std::clamp(folded, 0.0, length);
}

struct Pose {
    glm::dvec3 translation;
    glm::dquat rotation;
    glm::dvec3 scale;
};

glm::dmat4 poseMatrix(const Pose& pose) {
    return glm::scale(glm::translate(glm::dmat4(1.0), pose.translation) * glm::mat4_cast(pose.rotation),
                      pose.scale);
}

// World transforms of every animation node at `time`: rest poses, with each clip's channels
// applied at the clip's own looped time, composed parents first.
std::vector<glm::dmat4> nodeWorlds(const SceneAnimation& animation, double time) {
    std::vector<Pose> poses;
    poses.reserve(animation.nodes.size());
    for (const AnimationNode& node : animation.nodes) {
        poses.push_back({node.translation, node.rotation, node.scale});
    }
    std::vector<bool> animated(animation.nodes.size(), false);
    for (const NodeClip& clip : animation.clips) {
        const double local = loopTime(time, clip.length);
        for (const NodeChannel& channel : clip.channels) {
            Pose& pose = poses[channel.node];
            animated[channel.node] = true;
            switch (channel.property) {
            case NodeProperty::Translation:
                pose.translation = glm::dvec3(sample(channel.vectorKeys, local));
                break;
            case NodeProperty::Rotation:
                pose.rotation = glm::dquat(sample(channel.rotationKeys, local));
                break;
            case NodeProperty::Scale:
                pose.scale = glm::dvec3(sample(channel.vectorKeys, local));
                break;
            }
        }
    }
    std::vector<glm::dmat4> worlds(animation.nodes.size());
    for (size_t i = 0; i < animation.nodes.size(); ++i) {
        const AnimationNode& node = animation.nodes[i];
        const glm::dmat4 local = node.useMatrix && !animated[i] ? node.matrix : poseMatrix(poses[i]);
        worlds[i] = node.parent >= 0 ? worlds[size_t(node.parent)] * local : local;
    }
    return worlds;
}

void applyNodeAnimation(const SceneAnimation& animation, double time, Scene& scene) {
    if (animation.nodeInstances.empty() && animation.nodeLights.empty()) {
        return;
    }
    const std::vector<glm::dmat4> worlds = nodeWorlds(animation, time);
    for (const NodeBinding& binding : animation.nodeInstances) {
        scene.instances[binding.target].transform = glm::mat4(worlds[binding.node]);
    }
    for (const NodeBinding& binding : animation.nodeLights) {
        Light& light = scene.lights[binding.target];
        const glm::dmat4& world = worlds[binding.node];
        light.position = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
        const glm::dvec3 direction = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
        if (glm::length(direction) > 0.0) { // a zero scale keeps the last direction
            light.direction = glm::vec3(glm::normalize(direction));
        }
    }
}

void applyInstancePath(const InstancePath& path, double time, Instance& instance) {
    glm::mat4 transform = path.rest;
    if (!path.rotation.empty()) {
        transform = glm::translate(glm::mat4(1.0f), path.pivot) *
                    glm::mat4_cast(sample(path.rotation, time)) *
                    glm::translate(glm::mat4(1.0f), -path.pivot) * transform;
    }
    if (!path.translation.empty()) {
        transform = glm::translate(glm::mat4(1.0f), sample(path.translation, time)) * transform;
    }
    instance.transform = transform;
}

bool switchedOff(const Keyframes<float>& on, double time) {
    return !on.empty() && sample(on, time) < 0.5f;
}

void applyLightPath(const LightPath& path, double time, Light& light) {
    if (!path.position.empty()) {
        light.position = sample(path.position, time);
    }
    if (!path.direction.empty()) {
        const glm::vec3 direction = sample(path.direction, time);
        if (glm::length(direction) > 1e-6f) { // keys pointing opposite ways pass through zero
            light.direction = glm::normalize(direction);
        }
    }
    if (!path.sunDegrees.empty()) {
        light.direction = sunDirection(sample(path.sunDegrees, time));
    }
    if (!path.color.empty()) {
        light.color = sample(path.color, time);
    }
    if (!path.intensity.empty()) {
        light.intensity = sample(path.intensity, time);
    } else if (!path.on.empty()) {
        light.intensity = path.restIntensity;
    }
    if (switchedOff(path.on, time)) {
        light.intensity = 0.0f;
    }
}

void applyMaterialPath(const MaterialPath& path, double time, Material& material) {
    if (!path.emission.empty()) {
        material.emission = sample(path.emission, time);
    } else if (!path.on.empty()) {
        material.emission = path.restEmission;
    }
    if (switchedOff(path.on, time)) {
        material.emission = glm::vec3(0.0f);
    }
}

std::vector<uint32_t> sortedUnique(std::vector<uint32_t> indices) {
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    return indices;
}

} // namespace

const char* nodePropertyName(NodeProperty property) {
    switch (property) {
    case NodeProperty::Translation:
        return "translation";
    case NodeProperty::Rotation:
        return "rotation";
    case NodeProperty::Scale:
        return "scale";
    }
    return "unknown";
}

glm::vec3 sunDirection(const glm::vec2& azimuthElevationDegrees) {
    const float azimuth = glm::radians(azimuthElevationDegrees.x);
    const float elevation = glm::radians(azimuthElevationDegrees.y);
    const glm::vec3 towardsSun(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                               -std::cos(elevation) * std::cos(azimuth));
    return -glm::normalize(towardsSun);
}

double animationTime(uint64_t frame, double framesPerSecond) {
    return double(frame) / framesPerSecond;
}

bool SceneAnimation::empty() const {
    return nodeInstances.empty() && nodeLights.empty() && instancePaths.empty() && lightPaths.empty() &&
           materialPaths.empty();
}

double SceneAnimation::length() const {
    double length = 0.0;
    if (!nodeInstances.empty() || !nodeLights.empty()) {
        for (const NodeClip& clip : clips) {
            length = std::max(length, clip.length);
        }
    }
    if (scriptLoopSeconds > 0.0 &&
        (!instancePaths.empty() || !lightPaths.empty() || !materialPaths.empty())) {
        return std::max(length, scriptLoopSeconds);
    }
    for (const InstancePath& path : instancePaths) {
        length = std::max({length, path.translation.endTime(), path.rotation.endTime()});
    }
    for (const LightPath& path : lightPaths) {
        length =
            std::max({length, path.position.endTime(), path.direction.endTime(), path.sunDegrees.endTime(),
                      path.color.endTime(), path.intensity.endTime(), path.on.endTime()});
    }
    for (const MaterialPath& path : materialPaths) {
        length = std::max({length, path.emission.endTime(), path.on.endTime()});
    }
    return length;
}

std::vector<uint32_t> SceneAnimation::animatedInstances() const {
    std::vector<uint32_t> out;
    for (const NodeBinding& binding : nodeInstances) {
        out.push_back(binding.target);
    }
    for (const InstancePath& path : instancePaths) {
        out.push_back(path.instance);
    }
    return sortedUnique(std::move(out));
}

std::vector<uint32_t> SceneAnimation::animatedLights() const {
    std::vector<uint32_t> out;
    for (const NodeBinding& binding : nodeLights) {
        out.push_back(binding.target);
    }
    for (const LightPath& path : lightPaths) {
        out.push_back(path.light);
    }
    return sortedUnique(std::move(out));
}

std::vector<uint32_t> SceneAnimation::animatedMaterials() const {
    std::vector<uint32_t> out;
    for (const MaterialPath& path : materialPaths) {
        out.push_back(path.material);
    }
    return sortedUnique(std::move(out));
}

void animateScene(Scene& scene, uint64_t frame) {
    const SceneAnimation& animation = scene.animation;
    if (animation.empty()) {
        return;
    }
    const double time = animationTime(frame, scene.framesPerSecond);
    applyNodeAnimation(animation, time, scene);
    const double scriptTime =
        animation.scriptLoopSeconds > 0.0 ? loopTime(time, animation.scriptLoopSeconds) : time;
    for (const InstancePath& path : animation.instancePaths) {
        applyInstancePath(path, scriptTime, scene.instances[path.instance]);
    }
    for (const LightPath& path : animation.lightPaths) {
        applyLightPath(path, scriptTime, scene.lights[path.light]);
    }
    for (const MaterialPath& path : animation.materialPaths) {
        applyMaterialPath(path, scriptTime, scene.materials[path.material]);
    }
}

} // namespace lumina::scene
