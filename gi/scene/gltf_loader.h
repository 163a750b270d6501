#pragma once
// glTF 2.0 (.gltf and .glb) to the scene model, through tinygltf. Every index, accessor
// bound and number is checked; bad data is a SceneError naming the file and the problem,
// and the documented repairs (docs/scenes.md, "Bad input") are listed in Scene::report.
#include "gi/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <span>

namespace lumina::scene {

struct GltfLoadOptions {
    // Length of one unit of the file, for converting candela (units.h).
    double metresPerUnit = 1.0;
    // false: buffers and images may only be embedded (data: URIs, GLB chunk); the fuzzer
    // uses this so that no input reads the file system.
    bool allowExternalFiles = true;
    // Budgets over the whole file, so that no input can make the loader allocate without
    // bound (many primitives reading one accessor, many images decoding one small PNG).
    uint64_t maxVertices = uint64_t(1) << 28;
    uint64_t maxTextureBytes = uint64_t(16) << 30;
};

// Loads a .gltf or .glb file (chosen by extension, else by its first bytes).
Scene loadGltfFile(const std::filesystem::path& file, const GltfLoadOptions& options = {});

// Loads glTF bytes held in memory: `file` names them in errors, `baseDir` resolves URIs.
Scene loadGltfMemory(std::span<const uint8_t> bytes, bool binary, const std::filesystem::path& file,
                     const std::filesystem::path& baseDir, const GltfLoadOptions& options = {});

} // namespace lumina::scene
