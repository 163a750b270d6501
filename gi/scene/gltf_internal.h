#pragma once
// Shared by the glTF loader's translation units: the parsed model and where to report.
#include "gi/scene/gltf_loader.h"
#include "gi/scene/scene.h"
#include "gi/scene/scene_error.h"
#include "gi/scene/tinygltf.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lumina::scene::gltf {

// Limits that keep a malicious or broken file from exhausting memory; no real asset a
// real-time renderer draws comes near them.
inline constexpr uint64_t kMaxAccessorElements = uint64_t(1) << 26;
// An accessor without a bufferView is all zeros (plus sparse values): a few are legitimate,
// millions only a way to make the loader allocate.
inline constexpr uint64_t kMaxUnbackedAccessorElements = uint64_t(1) << 20;
inline constexpr uint64_t kMaxMeshVertices = uint64_t(1) << 28;
inline constexpr uint64_t kMaxInstances = uint64_t(1) << 24;
// Coordinates beyond this many scene units are refused as a broken scale: float positions
// there are spaced more than 8 units apart.
inline constexpr double kMaxCoordinate = 1e8;

struct Context {
    const tinygltf::Model& model;
    std::filesystem::path file;
    GltfLoadOptions options;
    LoadReport& report;

    [[noreturn]] void fail(const std::string& problem) const { throw SceneError(file, problem); }
    void warn(const std::string& message) const { report.warnings.push_back(message); }
};

// "mesh 3 'Wheel'" style names for messages.
std::string describe(const char* kind, size_t index, const std::string& name);

// gltf_materials.cpp: materials and the textures they use, in glTF order.
void convertMaterials(const Context& context, Scene& scene);

// gltf_textures.cpp: decodes glTF texture `textureIndex` (once per image, remembered in
// imageTexture) and returns its index in scene.textures.
uint32_t convertTexture(const Context& context, int textureIndex, const std::string& what, Scene& scene,
                        std::vector<int64_t>& imageTexture);

// gltf_meshes.cpp: glTF mesh -> scene mesh; meshIndex[i] is the scene mesh of glTF mesh i,
// or -1 when it has no triangles. `defaultMaterial` is used by primitives without one.
std::vector<int64_t> convertMeshes(const Context& context, Scene& scene, uint32_t defaultMaterial);

// The glTF node that made each instance and each light, parallel to scene.instances and
// scene.lights.
struct NodeOrigins {
    std::vector<int> instanceNode;
    std::vector<int> lightNode;
};

// gltf_nodes.cpp: walks the default scene's node trees into instances, lights and cameras.
NodeOrigins convertNodes(const Context& context, const std::vector<int64_t>& meshIndex, Scene& scene);

// gltf_animation.cpp: the glTF's animations as scene.animation's node clips, bound to the
// instances and lights under the animated nodes.
void convertAnimations(const Context& context, const NodeOrigins& origins, Scene& scene);

} // namespace lumina::scene::gltf
