#pragma once
// Animation in the scene model: what moves and changes over time, evaluated by frame number.
// Two sources fill it (docs/scenes.md, "Animation"):
//
// - glTF node animations (gltf_animation.cpp): channels drive the translation, rotation and
//   scale of nodes; the world transforms of the instances and lights under an animated node
//   follow through the node hierarchy. Each glTF animation loops over its own length.
// - scripted changes in the scene file (scene_file_animation.cpp): object paths, light paths,
//   the sun's path, emission and on/off toggles, keyed by frame or time. They loop over
//   `scriptLoopSeconds` when it is set, else hold their last keys.
//
// Time is frame / Scene::framesPerSecond, a fixed step. animateScene depends only on the
// animation and the frame number, never on earlier calls: tests and the bench replay it exactly.
#include "gi/scene/keyframes.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

namespace lumina::scene {

struct Scene;

// --- glTF node animation ---------------------------------------------------------------------

// A node of the glTF hierarchy that an animated instance or light hangs from: the animated
// nodes and their ancestors, parents before children. Its rest pose is the file's TRS, or its
// matrix (glTF forbids animating a node given by a matrix; the loader checks).
struct AnimationNode {
    std::string name;
    int32_t parent = -1; // index into SceneAnimation::nodes; -1 for a root
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
    bool useMatrix = false;
    glm::dmat4 matrix{1.0};
};

enum class NodeProperty { Translation, Rotation, Scale };

const char* nodePropertyName(NodeProperty property);

struct NodeChannel {
    uint32_t node = 0; // index into SceneAnimation::nodes
    NodeProperty property = NodeProperty::Translation;
    Keyframes<glm::vec3> vectorKeys{}; // translation or scale
    Keyframes<glm::quat> rotationKeys{};

    size_t keyCount() const {
        return property == NodeProperty::Rotation ? rotationKeys.times.size() : vectorKeys.times.size();
    }
};

// One glTF animation: its channels play together and loop over `length` seconds (the last key
// time of any of them).
struct NodeClip {
    std::string name;
    double length = 0.0;
    std::vector<NodeChannel> channels{};
};

// An instance or light placed by an animated node's world transform.
struct NodeBinding {
    uint32_t target = 0; // index into Scene::instances or Scene::lights
    uint32_t node = 0;   // index into SceneAnimation::nodes
};

// --- scripted changes (scene file) ------------------------------------------------------------

// An instance moved about its rest pose: at time t its transform is
//   translate(translation(t)) * translate(pivot) * rotate(rotation(t)) * translate(-pivot) * rest.
struct InstancePath {
    uint32_t instance = 0;
    glm::mat4 rest{1.0f};             // the transform it was loaded with
    glm::vec3 pivot{0.0f};            // world space: the point rotations turn about (a door's hinge)
    Keyframes<glm::vec3> translation{}; // world-space offset
    Keyframes<glm::quat> rotation{};
};

// Changes to one light. A light switched off (`on` below 0.5) has intensity 0; switched on it
// has its `intensity` track's value, or restIntensity. A sun path (azimuth and elevation in
// degrees, the direction towards the sun at azimuth a from -z towards +x and elevation e above
// the horizon: (cos e sin a, sin e, -cos e cos a)) drives `direction` as the opposite vector.
struct LightPath {
    uint32_t light = 0;
    float restIntensity = 0.0f;
    Keyframes<glm::vec3> position{};
    Keyframes<glm::vec3> direction{};  // where the light travels; normalised after interpolation
    Keyframes<glm::vec2> sunDegrees{}; // (azimuth, elevation)
    Keyframes<glm::vec3> color{};
    Keyframes<float> intensity{}; // scene units (units.h)
    Keyframes<float> on{};        // step keys of 1 and 0
};

// Changes to one material's emission (radiance); switched off it emits nothing.
struct MaterialPath {
    uint32_t material = 0;
    glm::vec3 restEmission{0.0f};
    Keyframes<glm::vec3> emission{};
    Keyframes<float> on{};
};

// The direction a sun at (azimuth, elevation) degrees sends its light (unit length).
glm::vec3 sunDirection(const glm::vec2& azimuthElevationDegrees);

struct SceneAnimation {
    // glTF
    std::vector<AnimationNode> nodes;
    std::vector<NodeClip> clips;
    std::vector<NodeBinding> nodeInstances;
    std::vector<NodeBinding> nodeLights;
    // scene file
    std::vector<InstancePath> instancePaths;
    std::vector<LightPath> lightPaths;
    std::vector<MaterialPath> materialPaths;
    double scriptLoopSeconds = 0.0; // 0: scripted tracks hold their last keys

    bool empty() const;
    // Seconds after which everything has played once: the longest clip, the script's loop, or
    // the script's last key when it does not loop. 0 when empty.
    double length() const;
    // Indices of what animateScene may change, sorted, each once: for a renderer that wants to
    // know which instances, lights and materials can move or change at all.
    std::vector<uint32_t> animatedInstances() const;
    std::vector<uint32_t> animatedLights() const;
    std::vector<uint32_t> animatedMaterials() const;
};

// Sets every animated property of `scene` to its value at `frame` (frame 0 = the first frame
// rendered): instance transforms, lights (position, direction, colour, intensity; a light
// switched off has intensity 0), material emission. Properties with no track are left
// untouched. Deterministic: depends only on the scene's animation and `frame`.
void animateScene(Scene& scene, uint64_t frame);

// The time animateScene evaluates for `frame`: frame / framesPerSecond, in seconds.
double animationTime(uint64_t frame, double framesPerSecond);

} // namespace lumina::scene
