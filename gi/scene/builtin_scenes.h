#pragma once
// The built-in scenes, addressable by name from every subcommand. Each lives in
// scenes/<name>/<name>.json; the small ones beside their glTF, written by the generator
// listed here (tests/scene/builtin_files_test.cpp checks the files still match it), atrium
// and city generated when their scene file is loaded.
#include "gi/scene/scene.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string_view>

namespace lumina::scene {

struct BuiltinScene {
    std::string_view name;
    // Makes the scene that scenes/<name>/ holds as files; null for scenes generated at load
    // and for scene files naming a glTF from elsewhere (two_cylinder_engine: assimp-testmodels).
    Scene (*make)() = nullptr;
};

std::span<const BuiltinScene> builtinScenes();
bool isBuiltinScene(std::string_view name);

// The folder holding the built-in scenes, first found of: $LUMINA_SCENES_DIR,
// $LUMINA_SOURCE_DIR/scenes, scenes/ beside the executable or up to three folders above it,
// and the source tree this library was built from.
std::optional<std::filesystem::path> findScenesDirectory();

} // namespace lumina::scene
