// glTF animations: node translation, rotation and scale channels become SceneAnimation clips;
// the instances and lights under an animated node are bound to the node whose world transform
// places them. Morph-target weights are not supported (a warning); every other problem with the
// animation data is an error naming the animation, channel and accessor.
#include "gi/scene/gltf_accessor.h"
#include "gi/scene/gltf_internal.h"

#include <cmath>
#include <map>
#include <set>

namespace lumina::scene::gltf {

namespace {

Interpolation samplerInterpolation(const Context& context, const std::string& name, const std::string& what) {
    if (name.empty() || name == "LINEAR") {
        return Interpolation::Linear;
    }
    if (name == "STEP") {
        return Interpolation::Step;
    }
    if (name == "CUBICSPLINE") {
        return Interpolation::CubicSpline;
    }
    context.fail(what + ": unknown interpolation '" + name + "' (LINEAR, STEP or CUBICSPLINE)");
}

std::vector<double> keyTimes(const Context& context, int accessor, const std::string& what) {
    const std::string where = what + " input";
    const std::vector<float> raw = readFloatAccessor(context, accessor, 1, where);
    if (context.model.accessors[size_t(accessor)].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
        context.fail(where + ": accessor " + std::to_string(accessor) +
                     " must hold floats (key times in seconds)");
    }
    if (raw.empty()) {
        context.fail(where + ": accessor " + std::to_string(accessor) + " has no keys");
    }
    std::vector<double> times(raw.begin(), raw.end());
    for (size_t k = 0; k < times.size(); ++k) {
        if (!std::isfinite(times[k]) || times[k] < 0.0) {
            context.fail(where + ": key " + std::to_string(k) + " time is " + std::to_string(times[k]) +
                         " (times are finite seconds, not negative)");
        }
        if (k > 0 && !(times[k] > times[k - 1])) {
            context.fail(where + ": key times are not increasing (key " + std::to_string(k) + " at " +
                         std::to_string(times[k]) + " s after " + std::to_string(times[k - 1]) + " s)");
        }
    }
    return times;
}

// The sampler's output as `components` floats per value, checked against the key count.
std::vector<float> keyValues(const Context& context, int accessor, int components, size_t values,
                             const std::string& what) {
    const std::string where = what + " output";
    const std::vector<float> raw = readFloatAccessor(context, accessor, components, where);
    if (raw.size() != values * size_t(components)) {
        context.fail(where + ": accessor " + std::to_string(accessor) + " has " +
                     std::to_string(raw.size() / size_t(components)) + " values, not the " +
                     std::to_string(values) + " its keys need");
    }
    for (size_t i = 0; i < raw.size(); ++i) {
        if (!std::isfinite(raw[i])) {
            context.fail(where + ": value " + std::to_string(i / size_t(components)) + " is not finite");
        }
        // As for static nodes (gltf_internal.h): beyond this, float positions lose their meaning.
        if (std::abs(raw[i]) > kMaxCoordinate) {
            context.fail(where + ": value " + std::to_string(i / size_t(components)) + " holds " +
                         std::to_string(raw[i]) + ", beyond the supported 1e8");
        }
    }
    return raw;
}

NodeChannel readChannel(const Context& context, const tinygltf::Animation& animation,
                        const tinygltf::AnimationChannel& channel, const std::string& what) {
    if (channel.sampler < 0 || size_t(channel.sampler) >= animation.samplers.size()) {
        context.fail(what + ": sampler " + std::to_string(channel.sampler) + " does not exist");
    }
    const tinygltf::AnimationSampler& sampler = animation.samplers[size_t(channel.sampler)];
    const tinygltf::Node& node = context.model.nodes[size_t(channel.target_node)];
    if (!node.matrix.empty()) {
        context.fail(what + ": its node " + std::to_string(channel.target_node) +
                     " has a matrix, and glTF animates only nodes given by translation, rotation and scale");
    }
    NodeChannel out;
    out.node = uint32_t(channel.target_node); // a glTF node index until convertAnimations renumbers it
    const Interpolation interpolation = samplerInterpolation(context, sampler.interpolation, what);
    std::vector<double> times = keyTimes(context, sampler.input, what);
    const size_t values = times.size() * (interpolation == Interpolation::CubicSpline ? 3 : 1);
    if (channel.target_path == "rotation") {
        out.property = NodeProperty::Rotation;
        const std::vector<float> raw = keyValues(context, sampler.output, 4, values, what);
        out.rotationKeys.interpolation = interpolation;
        out.rotationKeys.times = std::move(times);
        for (size_t v = 0; v < values; ++v) {
            // glTF stores x, y, z, w; glm's constructor takes w first.
            out.rotationKeys.values.emplace_back(raw[4 * v + 3], raw[4 * v], raw[4 * v + 1], raw[4 * v + 2]);
        }
        for (size_t k = 0; k < out.rotationKeys.times.size(); ++k) {
            if (!(glm::length(out.rotationKeys.keyValue(k)) > 1e-6f)) {
                context.fail(what + " output: key " + std::to_string(k) + " is a zero-length quaternion");
            }
        }
        return out;
    }
    out.property = channel.target_path == "scale" ? NodeProperty::Scale : NodeProperty::Translation;
    const std::vector<float> raw = keyValues(context, sampler.output, 3, values, what);
    out.vectorKeys.interpolation = interpolation;
    out.vectorKeys.times = std::move(times);
    for (size_t v = 0; v < values; ++v) {
        out.vectorKeys.values.emplace_back(raw[3 * v], raw[3 * v + 1], raw[3 * v + 2]);
    }
    return out;
}

// Every glTF animation as a clip of node channels (node indices still glTF's).
std::vector<NodeClip> readClips(const Context& context) {
    const tinygltf::Model& model = context.model;
    std::vector<NodeClip> clips;
    bool warnedWeights = false;
    uint64_t totalKeys = 0; // many channels may share one large accessor: bound the copies
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& animation = model.animations[a];
        NodeClip clip;
        clip.name = animation.name.empty() ? "animation " + std::to_string(a) : animation.name;
        std::set<std::pair<int, std::string>> targeted;
        for (size_t c = 0; c < animation.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = animation.channels[c];
            const std::string what =
                describe("animation", a, animation.name) + " channel " + std::to_string(c);
            if (channel.target_path == "weights") {
                if (!warnedWeights) {
                    context.warn(what + ": morph target weights are not supported; ignored");
                    warnedWeights = true;
                }
                continue;
            }
            if (channel.target_path != "translation" && channel.target_path != "rotation" &&
                channel.target_path != "scale") {
                context.fail(what + ": unknown target path '" + channel.target_path +
                             "' (translation, rotation, scale or weights)");
            }
            if (channel.target_node < 0 || size_t(channel.target_node) >= model.nodes.size()) {
                context.fail(what + ": target node " + std::to_string(channel.target_node) +
                             " does not exist");
            }
            if (!targeted.insert({channel.target_node, channel.target_path}).second) {
                context.fail(what + ": a second channel for the " + channel.target_path + " of node " +
                             std::to_string(channel.target_node));
            }
            NodeChannel read = readChannel(context, animation, channel, what);
            totalKeys += read.keyCount();
            if (totalKeys > kMaxAccessorElements) {
                context.fail(what + ": the animations hold more than " +
                             std::to_string(kMaxAccessorElements) + " keys in all");
            }
            clip.length =
                std::max(clip.length, read.property == NodeProperty::Rotation ? read.rotationKeys.endTime()
                                                                              : read.vectorKeys.endTime());
            clip.channels.push_back(std::move(read));
        }
        if (!clip.channels.empty()) {
            clips.push_back(std::move(clip));
        }
    }
    return clips;
}

AnimationNode restNode(const tinygltf::Node& node, size_t index) {
    AnimationNode out;
    out.name = node.name.empty() ? "node " + std::to_string(index) : node.name;
    if (node.matrix.size() == 16) {
        out.useMatrix = true;
        for (int i = 0; i < 16; ++i) {
            out.matrix[i / 4][i % 4] = node.matrix[size_t(i)];
        }
        return out;
    }
    if (node.translation.size() == 3) {
        out.translation = {node.translation[0], node.translation[1], node.translation[2]};
    }
    if (node.rotation.size() == 4) { // convertNodes checked it is not zero
        out.rotation = glm::normalize(
            glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    }
    if (node.scale.size() == 3) {
        out.scale = {node.scale[0], node.scale[1], node.scale[2]};
    }
    return out;
}

} // namespace

void convertAnimations(const Context& context, const NodeOrigins& origins, Scene& scene) {
    const tinygltf::Model& model = context.model;
    std::vector<NodeClip> clips = readClips(context);
    if (clips.empty()) {
        return;
    }
    // The hierarchy is a set of trees (convertNodes checked): each node has at most one parent.
    std::vector<int> parent(model.nodes.size(), -1);
    for (size_t i = 0; i < model.nodes.size(); ++i) {
        for (int child : model.nodes[i].children) {
            parent[size_t(child)] = int(i);
        }
    }
    std::vector<bool> animated(model.nodes.size(), false);
    for (const NodeClip& clip : clips) {
        for (const NodeChannel& channel : clip.channels) {
            animated[channel.node] = true;
        }
    }
    // Whether a node or any ancestor is animated, memoised so that a long chain of nodes costs
    // linear time, not quadratic.
    std::vector<int8_t> moving(model.nodes.size(), -1);
    auto moves = [&](int node) {
        std::vector<int> chain;
        int n = node;
        for (; n >= 0 && moving[size_t(n)] < 0; n = parent[size_t(n)]) {
            chain.push_back(n);
        }
        bool value = n >= 0 && moving[size_t(n)] == 1;
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            value = value || animated[size_t(*it)];
            moving[size_t(*it)] = value ? 1 : 0;
        }
        return moving[size_t(node)] == 1;
    };
    // Keep the nodes that place a moving instance or light, and their ancestors, parents first.
    std::map<int, uint32_t> kept;
    SceneAnimation& animation = scene.animation;
    // Iterative, not recursive: a hostile file may chain a million nodes.
    auto keep = [&](int node) -> uint32_t {
        std::vector<int> chain; // node, its parent, ... up to the first ancestor already kept
        for (int n = node; n >= 0 && !kept.count(n); n = parent[size_t(n)]) {
            chain.push_back(n);
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            AnimationNode rest = restNode(model.nodes[size_t(*it)], size_t(*it));
            const int up = parent[size_t(*it)];
            rest.parent = up >= 0 ? int32_t(kept.at(up)) : -1;
            animation.nodes.push_back(std::move(rest));
            kept[*it] = uint32_t(animation.nodes.size() - 1);
        }
        return kept.at(node);
    };
    for (size_t i = 0; i < origins.instanceNode.size(); ++i) {
        if (moves(origins.instanceNode[i])) {
            animation.nodeInstances.push_back({uint32_t(i), keep(origins.instanceNode[i])});
        }
    }
    for (size_t i = 0; i < origins.lightNode.size(); ++i) {
        if (moves(origins.lightNode[i])) {
            animation.nodeLights.push_back({uint32_t(i), keep(origins.lightNode[i])});
        }
    }
    if (animation.nodeInstances.empty() && animation.nodeLights.empty()) {
        context.warn(std::to_string(clips.size()) + " animation(s) move no instance or light; ignored");
        return;
    }
    for (NodeClip& clip : clips) {
        std::vector<NodeChannel> channels;
        for (NodeChannel& channel : clip.channels) {
            if (const auto it = kept.find(int(channel.node)); it != kept.end()) {
                channel.node = it->second;
                channels.push_back(std::move(channel));
            }
        }
        clip.channels = std::move(channels);
        if (!clip.channels.empty()) {
            animation.clips.push_back(std::move(clip));
        }
    }
}

} // namespace lumina::scene::gltf
