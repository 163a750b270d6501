#include "app/commands/scene_options.h"

#include "gi/scene/default_light.h"
#include "gi/scene/scene_animation.h"

#include <cmath>

namespace lumina::app {

std::vector<FlagSpec> sceneLoadFlags() {
    return {
        {"no-default-light", "",
         "keep a scene without any light black (default: it gets the default sun and sky, docs/scenes.md)"},
        {"sky", "FILE.exr", "an equirectangular EXR environment that replaces the scene's sky"},
        {"sky-intensity", "K", "factor on the --sky environment's texels (default 1)"}};
}

std::vector<FlagSpec> withSceneLoadFlags(std::vector<FlagSpec> flags) {
    for (const FlagSpec& flag : sceneLoadFlags()) {
        flags.push_back(flag);
    }
    return flags;
}

scene::LoadOptions sceneLoadOptions(const ParsedArgs& args) {
    scene::LoadOptions options;
    options.defaultLight = !args.has("no-default-light");
    if (args.has("sky")) {
        options.skyEnvironment = args.get("sky");
    }
    if (args.has("sky-intensity")) {
        if (!args.has("sky")) {
            throw UsageError("--sky-intensity: applies to a --sky environment, and none is given");
        }
        const double intensity = args.getDouble("sky-intensity", 1.0);
        if (!(intensity >= 0.0) || !std::isfinite(float(intensity))) {
            throw UsageError("--sky-intensity: must be a finite number, not negative, got " +
                             args.get("sky-intensity"));
        }
        options.skyIntensity = float(intensity);
    }
    return options;
}

bool poseAtAnimationFrame(const ParsedArgs& args, scene::Scene& scene) {
    if (!args.has("animation-frame")) {
        return false;
    }
    if (scene.animation.empty()) {
        throw UsageError("--animation-frame: scene '" + scene.name + "' has no animation");
    }
    scene::animateScene(scene, args.getUint("animation-frame", 0, 0, UINT32_MAX));
    return true;
}

std::string lightingLine(const scene::Scene& scene) {
    if (scene.defaultLight) {
        return "lights: none in the file; added the default sun and sky (--no-default-light turns this off)";
    }
    if (!scene::sceneHasLight(scene)) {
        return "lights: none (no light, emissive material or sky), and the default light is off: the image "
               "is "
               "black";
    }
    size_t emissive = 0;
    for (const scene::Material& material : scene.materials) {
        emissive += glm::any(glm::greaterThan(material.emission, glm::vec3(0.0f))) ? 1 : 0;
    }
    std::string line = "lights: " + std::to_string(scene.lights.size()) + " light(s), " +
                       std::to_string(emissive) + " emissive material(s), ";
    if (scene.skyEnvironment) {
        line += "sky environment " + scene.skyEnvironment->file.generic_string() + " (" +
                std::to_string(scene.skyEnvironment->width) + "x" +
                std::to_string(scene.skyEnvironment->height) + ")";
    } else {
        line += scene.hasSky() ? "a uniform sky" : "a black sky";
    }
    return line;
}

} // namespace lumina::app
