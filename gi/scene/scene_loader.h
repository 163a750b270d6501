#pragma once
// The one entry point the renderer, the path tracer and the tests use: a built-in scene's
// name ("cornell_box", "furnace_0.8") or a path to a scene file (.json) or glTF (.gltf,
// .glb) in, a Scene out. After the file, the options: the sky environment replaces the sky,
// then a scene left without any light gets the default sun and sky.
#include "gi/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

namespace lumina::scene {

struct LoadOptions {
    // Overrides the city generator's building count (`lumina info city --instances N`).
    std::optional<uint32_t> instances = std::nullopt;
    // A scene with no light of any kind gets the default sun and sky (default_light.h);
    // false keeps it black (`--no-default-light`).
    bool defaultLight = true;
    // An equirectangular EXR that replaces the scene's sky (`--sky FILE.exr`), its texels
    // times skyIntensity.
    std::optional<std::filesystem::path> skyEnvironment = std::nullopt;
    float skyIntensity = 1.0f;
};

// The file a name or path stands for: an existing file as is, else a built-in's scene file.
std::filesystem::path resolveScene(std::string_view nameOrPath);

Scene loadScene(std::string_view nameOrPath, const LoadOptions& options = {});

// A scene file: its glTF or generator, then its overrides.
Scene loadSceneFile(const std::filesystem::path& file, const LoadOptions& options = {});

} // namespace lumina::scene
