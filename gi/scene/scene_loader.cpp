#include "gi/scene/scene_loader.h"

#include "gi/scene/builtin_scenes.h"
#include "gi/scene/default_light.h"
#include "gi/scene/generators/generators.h"
#include "gi/scene/gltf_loader.h"
#include "gi/scene/scene_error.h"
#include "gi/scene/scene_file.h"
#include "gi/scene/sky_environment.h"

#include <cctype>
#include <string>

namespace lumina::scene {

namespace {

namespace fs = std::filesystem;

std::string builtinList() {
    std::string list;
    for (const BuiltinScene& scene : builtinScenes()) {
        list += (list.empty() ? "" : ", ") + std::string(scene.name);
    }
    return list;
}

Scene generate(const SceneFile& sceneFile, const LoadOptions& options) {
    if (sceneFile.generator == "atrium") {
        return makeAtrium();
    }
    if (sceneFile.generator == "door") {
        return makeDoor(sceneFile.doorGap.value_or(kDoorDefaultGap));
    }
    const uint32_t buildings =
        options.instances.value_or(sceneFile.instances.value_or(kCityDefaultBuildings));
    if (buildings < 1 || buildings > kCityMaxBuildings) {
        throw SceneError(sceneFile.file, "city instance count " + std::to_string(buildings) +
                                             " is outside [1, " + std::to_string(kCityMaxBuildings) + "]");
    }
    return makeCity(buildings);
}

// What LoadOptions add to a loaded scene, in order: the sky, then the default light.
Scene finishLighting(Scene scene, const LoadOptions& options) {
    if (options.skyEnvironment) {
        scene.skyEnvironment = readSkyEnvironment(*options.skyEnvironment, options.skyIntensity);
    }
    if (options.defaultLight && !sceneHasLight(scene)) {
        addDefaultLight(scene);
    }
    return scene;
}

Scene loadWithoutOptions(const fs::path& file, const std::string& extension, const LoadOptions& options) {
    if (extension == ".gltf" || extension == ".glb") {
        if (options.instances) {
            throw SceneError(file,
                             "an instance count applies only to generated scenes with instances (city)");
        }
        return loadGltfFile(file);
    }
    if (extension != ".json") {
        throw SceneError(file, "unknown kind of file '" + extension +
                                   "' (scene files end in .json, glTF files in .gltf or .glb)");
    }
    const SceneFile sceneFile = parseSceneFile(file);
    if (options.instances && sceneFile.generator != "city") {
        throw SceneError(file, "an instance count applies only to generated scenes with instances (city)");
    }
    Scene scene;
    if (!sceneFile.generator.empty()) {
        scene = generate(sceneFile, options);
        scene.generator = sceneFile.generator;
    } else {
        scene = loadGltfFile(sceneFile.gltf, {.metresPerUnit = sceneFile.metresPerUnit.value_or(1.0)});
    }
    scene.name = file.stem().string();
    applySceneFile(sceneFile, scene);
    animateScene(scene, 0); // a loaded scene shows its first frame
    finishCamera(scene);
    return scene;
}

} // namespace

fs::path resolveScene(std::string_view nameOrPath) {
    const fs::path path{std::string(nameOrPath)};
    std::error_code error;
    if (fs::is_regular_file(path, error)) {
        return path;
    }
    if (isBuiltinScene(nameOrPath)) {
        const std::optional<fs::path> dir = findScenesDirectory();
        if (!dir) {
            throw SceneError(path,
                             "built-in scene, but the scenes folder was not found (set LUMINA_SCENES_DIR or "
                             "LUMINA_SOURCE_DIR)");
        }
        return *dir / path / (std::string(nameOrPath) + ".json");
    }
    if (fs::exists(path, error)) {
        throw SceneError(path, "not a regular file");
    }
    throw SceneError(path, "no such file, and not a built-in scene (" + builtinList() + ")");
}

Scene loadSceneFile(const fs::path& file, const LoadOptions& options) {
    return finishLighting(loadWithoutOptions(file, ".json", options), options);
}

Scene loadScene(std::string_view nameOrPath, const LoadOptions& options) {
    const fs::path file = resolveScene(nameOrPath);
    std::string extension = file.extension().string();
    for (char& c : extension) {
        c = char(std::tolower(static_cast<unsigned char>(c)));
    }
    return finishLighting(loadWithoutOptions(file, extension, options), options);
}

} // namespace lumina::scene
