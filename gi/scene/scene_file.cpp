#include "gi/scene/scene_file.h"

#include "gi/scene/generators/generators.h"
#include "gi/scene/json_reader.h"
#include "gi/scene/scene_error.h"
#include "gi/scene/sky_environment.h"
#include "gi/scene/units.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace lumina::scene {

namespace {

// Largest image side, as the CLI's --size accepts.
constexpr uint32_t kMaxImageSide = 16384;
// Animation frame rates accepted: a fixed step of at most a second, at least a tenth of a millisecond.
constexpr double kMinFramesPerSecond = 1.0;
constexpr double kMaxFramesPerSecond = 10000.0;

glm::vec3 unitVector(const JsonObject& object, std::string_view key, const glm::vec3& v) {
    const float length = glm::length(v);
    if (!(length > 1e-6f)) {
        object.fail(key, "must not be a zero vector");
    }
    return v / length;
}

float angleDegrees(const JsonObject& object, std::string_view key, double min, double max, double fallback) {
    const double value = object.number(key).value_or(fallback);
    if (value < min || value > max) {
        object.fail(key, "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "] degrees");
    }
    return float(glm::radians(value));
}

// Only names the renderer can look up: lower case, digits, '_' and '-'.
std::string identifier(const JsonObject& object, std::string_view key, const std::string& value) {
    if (value.empty() ||
        value.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") != std::string::npos) {
        object.fail(key, "must be a name of lower-case letters, digits, '_' or '-', not '" + value + "'");
    }
    return value;
}

// Most probes along one axis of a DDGI volume (its probe buffer holds at most 65535 in all).
constexpr uint32_t kMaxProbesPerAxis = 256;

ProbeVolume parseProbeVolume(const nlohmann::json& value, const std::string& where,
                             const std::filesystem::path& file) {
    const JsonObject object(value, where, file, {"min", "max", "probes"});
    const std::optional<glm::vec3> min = object.vec3("min");
    const std::optional<glm::vec3> max = object.vec3("max");
    if (!min || !max || !glm::all(glm::lessThan(*min, *max))) {
        object.fail("max", "min and max are required, max above min on every axis");
    }
    ProbeVolume volume{.box = {*min, *max}};
    if (const nlohmann::json* probes = object.array("probes")) {
        if (probes->size() != 3) {
            object.fail("probes", "must be [x, y, z] probe counts");
        }
        for (int axis = 0; axis < 3; ++axis) {
            const nlohmann::json& count = (*probes)[size_t(axis)];
            if (!count.is_number_unsigned() || count.get<uint32_t>() < 2 ||
                count.get<uint32_t>() > kMaxProbesPerAxis) {
                object.fail("probes",
                            "each count must be an integer from 2 to " + std::to_string(kMaxProbesPerAxis));
            }
            volume.counts[axis] = count.get<uint32_t>();
        }
    }
    return volume;
}

Light parseLight(const nlohmann::json& value, const std::string& where, const std::filesystem::path& file) {
    const JsonObject object(value, where, file,
                            {"name", "type", "color", "intensity", "range", "position", "direction",
                             "innerConeDegrees", "outerConeDegrees"});
    Light light;
    const std::optional<std::string> type = object.string("type");
    if (!type) {
        object.fail("type", "is required (directional, point or spot)");
    }
    if (*type == "directional") {
        light.type = LightType::Directional;
    } else if (*type == "point") {
        light.type = LightType::Point;
    } else if (*type == "spot") {
        light.type = LightType::Spot;
    } else {
        object.fail("type", "must be directional, point or spot, not '" + *type + "'");
    }
    light.name = object.string("name").value_or(where);
    light.color = object.vec3("color").value_or(glm::vec3(1.0f));
    if (glm::any(glm::lessThan(light.color, glm::vec3(0.0f)))) {
        object.fail("color", "must not be negative");
    }
    const std::optional<double> intensity = object.number("intensity");
    if (!intensity || *intensity < 0.0) {
        object.fail("intensity",
                    "is required and must not be negative (lux for directional, candela otherwise)");
    }
    light.intensity = float(*intensity);
    light.range = float(object.number("range").value_or(0.0));
    if (light.range < 0.0f) {
        object.fail("range", "must not be negative (0: unlimited)");
    }
    if (light.type != LightType::Directional) {
        const std::optional<glm::vec3> position = object.vec3("position");
        if (!position) {
            object.fail("position", "is required for a " + *type + " light");
        }
        light.position = *position;
    } else if (object.has("position")) {
        object.fail("position", "has no meaning for a directional light");
    }
    if (light.type != LightType::Point) {
        const std::optional<glm::vec3> direction = object.vec3("direction");
        if (!direction) {
            object.fail("direction", "is required for a " + *type + " light (where its light travels)");
        }
        light.direction = unitVector(object, "direction", *direction);
    } else if (object.has("direction")) {
        object.fail("direction", "has no meaning for a point light");
    }
    if (light.type == LightType::Spot) {
        light.innerConeAngle = angleDegrees(object, "innerConeDegrees", 0.0, 90.0, 0.0);
        light.outerConeAngle = angleDegrees(object, "outerConeDegrees", 0.0, 90.0, 45.0);
        if (light.innerConeAngle >= light.outerConeAngle) {
            object.fail("innerConeDegrees", "must be less than outerConeDegrees");
        }
    } else if (object.has("innerConeDegrees") || object.has("outerConeDegrees")) {
        object.fail(object.has("innerConeDegrees") ? "innerConeDegrees" : "outerConeDegrees",
                    "applies to spot lights only");
    }
    return light;
}

SceneFileCamera parseCamera(const nlohmann::json& value, const std::filesystem::path& file) {
    const JsonObject object(value, "camera", file,
                            {"position", "lookAt", "forward", "up", "fovYDegrees", "near", "far"});
    SceneFileCamera camera;
    camera.position = object.vec3("position");
    camera.lookAt = object.vec3("lookAt");
    camera.forward = object.vec3("forward");
    camera.up = object.vec3("up");
    if (camera.lookAt && camera.forward) {
        object.fail("lookAt", "and 'camera.forward' cannot both be given");
    }
    if (camera.forward) {
        camera.forward = unitVector(object, "forward", *camera.forward);
    }
    if (camera.up) {
        camera.up = unitVector(object, "up", *camera.up);
    }
    if (const auto fov = object.number("fovYDegrees")) {
        if (*fov <= 0.0 || *fov >= 180.0) {
            object.fail("fovYDegrees", "must be in (0, 180)");
        }
        camera.fovYDegrees = float(*fov);
    }
    if (const auto nearPlane = object.number("near")) {
        if (*nearPlane <= 0.0) {
            object.fail("near", "must be positive");
        }
        camera.nearPlane = float(*nearPlane);
    }
    if (const auto farPlane = object.number("far")) {
        if (*farPlane <= camera.nearPlane.value_or(0.0f)) {
            object.fail("far", "must be greater than near");
        }
        camera.farPlane = float(*farPlane);
    }
    return camera;
}

// "sky": a uniform radiance [r, g, b], or {"environment": "file.exr", "intensity": k}.
void parseSky(const JsonObject& root, const nlohmann::json& document, SceneFile& out) {
    if (!root.has("sky")) {
        return;
    }
    if (!document["sky"].is_object()) {
        out.sky = root.vec3("sky");
        if (glm::any(glm::lessThan(*out.sky, glm::vec3(0.0f)))) {
            root.fail("sky", "must not be negative");
        }
        return;
    }
    const JsonObject object(*root.object("sky"), "sky", out.file, {"environment", "intensity"});
    const std::optional<std::string> environment = object.string("environment");
    if (!environment || environment->empty()) {
        object.fail("environment", "is required: an equirectangular .exr, relative to the scene file");
    }
    out.skyEnvironment = out.file.parent_path() / std::filesystem::path(*environment);
    const double intensity = object.number("intensity").value_or(1.0);
    if (!(intensity >= 0.0) || !std::isfinite(float(intensity))) {
        object.fail("intensity", "must be a finite number, not negative");
    }
    out.skyIntensity = float(intensity);
}

} // namespace

SceneFile parseSceneFileText(std::string_view text, const std::filesystem::path& file) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text.begin(), text.end(), nullptr, true, /*ignore_comments=*/true);
    } catch (const nlohmann::json::exception& error) {
        throw SceneError(file, std::string("malformed JSON: ") + error.what());
    }
    const JsonObject root(document, "", file,
                          {"description", "gltf", "generator", "instances", "doorGap", "metresPerUnit",
                           "camera", "lights", "replaceLights", "sun", "sky", "image", "technique", "preset",
                           "framesPerSecond", "animation", "ddgiVolumes"});
    SceneFile out;
    out.file = file;
    out.description = root.string("description").value_or("");
    const std::optional<std::string> gltf = root.string("gltf");
    const std::optional<std::string> generator = root.string("generator");
    if (gltf.has_value() == generator.has_value()) {
        throw SceneError(file,
                         "a scene file names exactly one of 'gltf' (a .gltf or .glb path) and 'generator'");
    }
    if (gltf) {
        if (gltf->empty()) {
            root.fail("gltf", "must not be empty");
        }
        out.gltf = file.parent_path() / std::filesystem::path(*gltf);
    } else {
        if (*generator != "atrium" && *generator != "city" && *generator != "door") {
            root.fail("generator", "must be atrium, city or door, not '" + *generator + "'");
        }
        out.generator = *generator;
    }
    out.instances = root.unsignedInt("instances", 1, kCityMaxBuildings);
    if (out.instances && out.generator != "city") {
        root.fail("instances", "applies only to \"generator\": \"city\"");
    }
    if (const auto gap = root.number("doorGap")) {
        if (out.generator != "door") {
            root.fail("doorGap", "applies only to \"generator\": \"door\"");
        }
        if (!(*gap >= kDoorMinGap && *gap <= kDoorMaxGap)) {
            std::ostringstream range;
            range << "must be within [" << kDoorMinGap << ", " << kDoorMaxGap << "] metres";
            root.fail("doorGap", range.str());
        }
        out.doorGap = float(*gap);
    }
    if (const auto metres = root.number("metresPerUnit")) {
        if (!(*metres > 0.0)) {
            root.fail("metresPerUnit", "must be positive");
        }
        out.metresPerUnit = *metres;
    }
    if (const nlohmann::json* camera = root.object("camera")) {
        out.camera = parseCamera(*camera, file);
    }
    if (const nlohmann::json* lights = root.array("lights")) {
        for (size_t i = 0; i < lights->size(); ++i) {
            out.lights.push_back(parseLight((*lights)[i], "lights[" + std::to_string(i) + "]", file));
        }
    }
    out.replaceLights = root.boolean("replaceLights").value_or(false);
    if (const nlohmann::json* sun = root.object("sun")) {
        const JsonObject object(*sun, "sun", file, {"direction", "color", "illuminance"});
        Light light{.type = LightType::Directional, .name = "sun"};
        const std::optional<glm::vec3> direction = object.vec3("direction");
        const std::optional<double> illuminance = object.number("illuminance");
        if (!direction) {
            object.fail("direction", "is required (where the sunlight travels, e.g. [0, -1, 0] at noon)");
        }
        if (!illuminance || *illuminance < 0.0) {
            object.fail("illuminance", "is required and must not be negative (lux)");
        }
        light.direction = unitVector(object, "direction", *direction);
        light.color = object.vec3("color").value_or(glm::vec3(1.0f));
        if (glm::any(glm::lessThan(light.color, glm::vec3(0.0f)))) {
            object.fail("color", "must not be negative");
        }
        light.intensity = float(*illuminance);
        out.sun = light;
    }
    parseSky(root, document, out);
    if (const nlohmann::json* image = root.object("image")) {
        const JsonObject object(*image, "image", file, {"width", "height"});
        const auto width = object.unsignedInt("width", 1, kMaxImageSide);
        const auto height = object.unsignedInt("height", 1, kMaxImageSide);
        if (!width || !height) {
            object.fail(width ? "height" : "width", "is required");
        }
        out.image = ImageSize{*width, *height};
    }
    if (const auto technique = root.string("technique")) {
        out.technique = identifier(root, "technique", *technique);
    }
    if (const auto preset = root.string("preset")) {
        out.preset = identifier(root, "preset", *preset);
    }
    if (const nlohmann::json* volumes = root.array("ddgiVolumes")) {
        for (size_t i = 0; i < volumes->size(); ++i) {
            out.probeVolumes.push_back(
                parseProbeVolume((*volumes)[i], "ddgiVolumes[" + std::to_string(i) + "]", file));
        }
    }
    if (const auto fps = root.number("framesPerSecond")) {
        if (*fps < kMinFramesPerSecond || *fps > kMaxFramesPerSecond) {
            root.fail("framesPerSecond", "must be in [" + std::to_string(int(kMinFramesPerSecond)) + ", " +
                                             std::to_string(int(kMaxFramesPerSecond)) + "]");
        }
        out.framesPerSecond = float(*fps);
    }
    if (const nlohmann::json* animation = root.object("animation")) {
        out.animation =
            parseScriptedAnimation(*animation, out.framesPerSecond.value_or(Scene{}.framesPerSecond), file);
    }
    return out;
}

SceneFile parseSceneFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::error_code error;
        throw SceneError(file, std::filesystem::exists(file, error) ? "cannot read" : "no such file");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parseSceneFileText(text.str(), file);
}

void applySceneFile(const SceneFile& sceneFile, Scene& scene) {
    scene.sourceFile = sceneFile.file;
    if (!sceneFile.description.empty()) {
        scene.description = sceneFile.description;
    }
    if (sceneFile.metresPerUnit) {
        scene.units.metresPerUnit = *sceneFile.metresPerUnit;
    }
    if (!sceneFile.probeVolumes.empty()) {
        scene.probeVolumes = sceneFile.probeVolumes;
    }
    if (sceneFile.replaceLights) {
        scene.lights.clear();
        scene.animation.nodeLights.clear(); // the glTF's animated lights are gone with them
    }
    if (sceneFile.framesPerSecond) {
        scene.framesPerSecond = *sceneFile.framesPerSecond;
    }
    std::vector<Light> added = sceneFile.lights;
    if (sceneFile.sun) {
        added.push_back(*sceneFile.sun);
    }
    for (Light& light : added) {
        if (light.type != LightType::Directional) {
            light.intensity = float(pointIntensityFromCandela(light.intensity, scene.units.metresPerUnit));
        }
        const glm::vec3 strength = light.strength();
        if (!std::isfinite(light.intensity) || !std::isfinite(strength.x + strength.y + strength.z)) {
            throw SceneError(sceneFile.file,
                             "light '" + light.name + "': its intensity overflows in scene units");
        }
        scene.lights.push_back(light);
    }
    if (sceneFile.sky) {
        scene.sky = *sceneFile.sky;
        scene.skyEnvironment.reset();
    }
    if (sceneFile.skyEnvironment) {
        scene.skyEnvironment = readSkyEnvironment(*sceneFile.skyEnvironment, sceneFile.skyIntensity);
    }
    if (sceneFile.image) {
        scene.image = *sceneFile.image;
    }
    if (sceneFile.technique) {
        scene.technique = *sceneFile.technique;
    }
    if (sceneFile.preset) {
        scene.preset = *sceneFile.preset;
    }
    if (sceneFile.animation) {
        resolveScriptedAnimation(*sceneFile.animation, sceneFile.file, scene);
    }
    if (!sceneFile.camera) {
        return;
    }
    const SceneFileCamera& c = *sceneFile.camera;
    Camera& camera = scene.camera;
    camera.position = c.position.value_or(camera.position);
    if (c.lookAt) {
        const glm::vec3 towards = *c.lookAt - camera.position;
        if (!(glm::length(towards) > 1e-6f)) {
            throw SceneError(sceneFile.file, "'camera.lookAt' is the camera's position");
        }
        camera.forward = glm::normalize(towards);
    }
    camera.forward = c.forward.value_or(camera.forward);
    const glm::vec3 up = c.up.value_or(c.forward || c.lookAt ? glm::vec3(0.0f, 1.0f, 0.0f) : camera.up);
    const glm::vec3 right = glm::cross(camera.forward, up);
    if (!(glm::length(right) > 1e-4f)) {
        throw SceneError(sceneFile.file, "'camera.up' is parallel to the camera's view direction");
    }
    camera.up = glm::normalize(glm::cross(glm::normalize(right), camera.forward));
    if (c.fovYDegrees) {
        camera.fovY = glm::radians(*c.fovYDegrees);
    }
    camera.nearPlane = c.nearPlane.value_or(camera.nearPlane);
    camera.farPlane = c.farPlane.value_or(camera.farPlane);
    if (camera.farPlane <= camera.nearPlane) {
        throw SceneError(sceneFile.file, "the camera's far plane is not beyond its near plane");
    }
    scene.cameraFromFile = true;
}

} // namespace lumina::scene
