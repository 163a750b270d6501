#pragma once
// Scene files: JSON that names a glTF (or a generator) and adds or overrides camera, lights,
// sun, sky, image size, GI technique and quality preset. docs/scenes.md is the schema; an
// unknown key is an error naming the key and the file.
#include "gi/scene/scene.h"
#include "gi/scene/scene_file_animation.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::scene {

struct SceneFileCamera {
    std::optional<glm::vec3> position;
    std::optional<glm::vec3> lookAt;
    std::optional<glm::vec3> forward;
    std::optional<glm::vec3> up;
    std::optional<float> fovYDegrees;
    std::optional<float> nearPlane;
    std::optional<float> farPlane;
};

struct SceneFile {
    std::filesystem::path file;
    std::string description;
    std::filesystem::path gltf;        // resolved against the scene file's folder; empty with a generator
    std::string generator;             // "atrium", "city" or "door"
    std::optional<uint32_t> instances; // city only
    std::optional<float> doorGap;      // door only: metres between the shut door and the wall
    std::optional<double> metresPerUnit;
    std::optional<SceneFileCamera> camera;
    std::vector<Light> lights; // intensities in file units (candela for point and spot)
    bool replaceLights = false;
    std::optional<Light> sun;
    std::optional<glm::vec3> sky;                        // "sky": [r, g, b]
    std::optional<std::filesystem::path> skyEnvironment; // "sky": {"environment": ...}, resolved
    float skyIntensity = 1.0f;                           // "sky": {"intensity": ...}
    std::optional<ImageSize> image;
    std::optional<std::string> technique;
    std::optional<std::string> preset;
    std::vector<ProbeVolume> probeVolumes; // "ddgiVolumes": [{"min", "max", "probes"}]
    std::optional<float> framesPerSecond;
    std::optional<ScriptedAnimation> animation; // frame keys already in seconds
};

SceneFile parseSceneFile(const std::filesystem::path& file);
SceneFile parseSceneFileText(std::string_view text, const std::filesystem::path& file);

// Applies everything the scene file sets on top of the scene its glTF or generator made.
void applySceneFile(const SceneFile& sceneFile, Scene& scene);

} // namespace lumina::scene
