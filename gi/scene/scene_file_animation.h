#pragma once
// The scene file's "animation" section: scripted object paths, light and sun paths, emission
// changes and toggles, keyed by frame or time (docs/scenes.md, "Scripted changes"). Parsing
// checks the keys alone; resolving finds the named instances, lights and materials in the
// loaded scene and turns the tracks into SceneAnimation paths.
#include "gi/scene/json_reader.h"
#include "gi/scene/scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lumina::scene {

// Tracks by name, times in seconds, values as the file gives them (intensities in its units).
struct ScriptedObject {
    std::string where; // "animation.objects[0]", for messages
    std::string instance;
    glm::vec3 pivot{0.0f};
    Keyframes<glm::vec3> translation;
    Keyframes<glm::quat> rotation;
};

struct ScriptedLight {
    std::string where;
    std::string light;
    Keyframes<glm::vec3> position;
    Keyframes<glm::vec3> direction;
    Keyframes<glm::vec2> sunDegrees;
    Keyframes<glm::vec3> color;
    Keyframes<float> intensity; // lux for directional lights, candela otherwise
    Keyframes<float> on;
};

struct ScriptedMaterial {
    std::string where;
    std::string material;
    Keyframes<glm::vec3> emission;
    Keyframes<float> on;
};

struct ScriptedAnimation {
    double loopSeconds = 0.0; // 0: hold the last keys
    std::vector<ScriptedObject> objects;
    std::vector<ScriptedLight> lights; // the "sun" section comes last
    std::vector<ScriptedMaterial> materials;
};

// Reads root["animation"]; frame keys become seconds at `framesPerSecond`.
ScriptedAnimation parseScriptedAnimation(const nlohmann::json& value, double framesPerSecond,
                                         const std::filesystem::path& file);

// Adds the scripted tracks to scene.animation, naming the file and the entry in every error
// (an unknown or ambiguous name, a track that does not fit the light's type, an instance a glTF
// animation already moves).
void resolveScriptedAnimation(const ScriptedAnimation& script, const std::filesystem::path& file,
                              Scene& scene);

} // namespace lumina::scene
