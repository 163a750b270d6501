#include "gi/scene/scene_file_animation.h"

#include "gi/scene/scene_error.h"
#include "gi/scene/units.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace lumina::scene {

namespace {

// Beyond any animation a renderer plays: a day at 60 frames per second is 5.2 million frames.
constexpr double kMaxKeySeconds = 1e7;
// Positions, offsets and pivots beyond this many scene units are refused, as the glTF loader
// refuses such geometry: float positions there are spaced more than 8 units apart.
constexpr float kMaxCoordinate = 1e8f;

std::string formatTime(double seconds) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g s", seconds);
    return text;
}

// The key's time in seconds from exactly one of "frame" (at `framesPerSecond`) and "time";
// later than `previous` unless it is the entry's first key.
double keyTime(const JsonObject& key, double framesPerSecond, std::optional<double> previous) {
    if (key.has("frame") == key.has("time")) {
        key.fail("frame", "or 'time' (seconds): a key has exactly one of them");
    }
    double time = 0.0;
    if (key.has("frame")) {
        time = double(*key.unsignedInt("frame", 0, std::numeric_limits<uint32_t>::max())) / framesPerSecond;
    } else {
        time = *key.number("time");
        if (time < 0.0 || time > kMaxKeySeconds) {
            key.fail("time", "must be in [0, " + std::to_string(kMaxKeySeconds) + "] seconds");
        }
    }
    if (previous && !(time > *previous)) {
        key.fail(key.has("frame") ? "frame" : "time", "must be later than the previous key's (" +
                                                          formatTime(*previous) +
                                                          "): keys are in time order");
    }
    return time;
}

Interpolation interpolation(const JsonObject& entry) {
    const std::string name = entry.string("interpolation").value_or("linear");
    if (name == "linear") {
        return Interpolation::Linear;
    }
    if (name == "step") {
        return Interpolation::Step;
    }
    entry.fail("interpolation", "must be linear or step, not '" + name + "'");
}

template <typename T>
void push(Keyframes<T>& track, double time, const T& value) {
    track.times.push_back(time);
    track.values.push_back(value);
}

// Calls readKey(key object path, its JSON, its time) for each of entry["keys"], which must be a
// non-empty array of keys in time order.
template <typename ReadKey>
void forEachKey(const JsonObject& entry, const std::string& where, ReadKey&& readKey) {
    const nlohmann::json* keys = entry.array("keys");
    if (!keys || keys->empty()) {
        entry.fail("keys", "is required: an array of at least one key");
    }
    for (size_t i = 0; i < keys->size(); ++i) {
        readKey(where + ".keys[" + std::to_string(i) + "]", (*keys)[i]);
    }
}

std::string requiredName(const JsonObject& entry, std::string_view key) {
    const std::optional<std::string> name = entry.string(key);
    if (!name || name->empty()) {
        entry.fail(key, "is required: the name of what the entry animates");
    }
    return *name;
}

glm::vec3 nonNegative(const JsonObject& key, std::string_view name, const glm::vec3& value) {
    if (glm::any(glm::lessThan(value, glm::vec3(0.0f)))) {
        key.fail(name, "must not be negative");
    }
    return value;
}

glm::vec3 withinReach(const JsonObject& key, std::string_view name, const glm::vec3& value) {
    if (glm::any(glm::greaterThan(glm::abs(value), glm::vec3(kMaxCoordinate)))) {
        key.fail(name, "must be within 1e8 scene units of the origin");
    }
    return value;
}

glm::vec3 unit(const JsonObject& key, std::string_view name, const glm::vec3& value) {
    if (!(glm::length(value) > 1e-6f)) {
        key.fail(name, "must not be a zero vector");
    }
    return glm::normalize(value);
}

glm::quat rotation(const nlohmann::json& value, const std::string& where, const std::filesystem::path& file) {
    const JsonObject object(value, where, file, {"axis", "degrees"});
    const std::optional<glm::vec3> axis = object.vec3("axis");
    const std::optional<double> degrees = object.number("degrees");
    if (!axis || !degrees) {
        object.fail(axis ? "degrees" : "axis", "is required (a rotation is an axis and an angle in degrees)");
    }
    return glm::angleAxis(float(glm::radians(*degrees)), unit(object, "axis", *axis));
}

ScriptedObject parseObject(const nlohmann::json& value, const std::string& where, double framesPerSecond,
                           const std::filesystem::path& file) {
    const JsonObject entry(value, where, file, {"instance", "pivot", "interpolation", "keys"});
    ScriptedObject out;
    out.where = where;
    out.instance = requiredName(entry, "instance");
    out.pivot = withinReach(entry, "pivot", entry.vec3("pivot").value_or(glm::vec3(0.0f)));
    out.translation.interpolation = out.rotation.interpolation = interpolation(entry);
    std::optional<double> previous;
    forEachKey(entry, where, [&](const std::string& keyWhere, const nlohmann::json& keyValue) {
        const JsonObject key(keyValue, keyWhere, file, {"frame", "time", "translation", "rotation"});
        const double time = keyTime(key, framesPerSecond, previous);
        previous = time;
        if (const auto translation = key.vec3("translation")) {
            push(out.translation, time, withinReach(key, "translation", *translation));
        }
        if (const nlohmann::json* r = key.object("rotation")) {
            push(out.rotation, time, rotation(*r, keyWhere + ".rotation", file));
        }
    });
    if (out.translation.empty() && out.rotation.empty()) {
        entry.fail("keys", "set neither 'translation' nor 'rotation'");
    }
    return out;
}

// A "lights" entry, or the "sun" section (`sun`: the light defaults to the one named "sun" and
// its intensity is "illuminance").
ScriptedLight parseLight(const nlohmann::json& value, const std::string& where, double framesPerSecond,
                         const std::filesystem::path& file, bool sun) {
    const JsonObject entry(value, where, file, {"light", "interpolation", "keys"});
    ScriptedLight out;
    out.where = where;
    out.light = sun ? entry.string("light").value_or("sun") : requiredName(entry, "light");
    const Interpolation mode = interpolation(entry);
    out.position.interpolation = out.direction.interpolation = out.color.interpolation = mode;
    out.sunDegrees.interpolation = out.intensity.interpolation = mode;
    out.on.interpolation = Interpolation::Step;
    const std::string_view intensityKey = sun ? "illuminance" : "intensity";
    std::optional<double> previous;
    forEachKey(entry, where, [&](const std::string& keyWhere, const nlohmann::json& keyValue) {
        const JsonObject key = sun ? JsonObject(keyValue, keyWhere, file,
                                                {"frame", "time", "azimuthDegrees", "elevationDegrees",
                                                 "illuminance", "color", "on"})
                                   : JsonObject(keyValue, keyWhere, file,
                                                {"frame", "time", "position", "direction", "azimuthDegrees",
                                                 "elevationDegrees", "color", "intensity", "on"});
        const double time = keyTime(key, framesPerSecond, previous);
        previous = time;
        if (const auto position = key.vec3("position")) {
            push(out.position, time, withinReach(key, "position", *position));
        }
        if (const auto direction = key.vec3("direction")) {
            push(out.direction, time, unit(key, "direction", *direction));
        }
        const std::optional<double> azimuth = key.number("azimuthDegrees");
        const std::optional<double> elevation = key.number("elevationDegrees");
        if (azimuth.has_value() != elevation.has_value()) {
            key.fail(azimuth ? "elevationDegrees" : "azimuthDegrees",
                     "is required with the other: a sun position is an azimuth and an elevation");
        }
        if (elevation && (*elevation < -90.0 || *elevation > 90.0)) {
            key.fail("elevationDegrees", "must be in [-90, 90]");
        }
        if (azimuth) {
            push(out.sunDegrees, time, glm::vec2(float(*azimuth), float(*elevation)));
        }
        if (const auto color = key.vec3("color")) {
            push(out.color, time, nonNegative(key, "color", *color));
        }
        if (const auto intensity = key.number(intensityKey)) {
            if (*intensity < 0.0) {
                key.fail(intensityKey, "must not be negative");
            }
            push(out.intensity, time, float(*intensity));
        }
        if (const auto on = key.boolean("on")) {
            push(out.on, time, *on ? 1.0f : 0.0f);
        }
    });
    if (!out.direction.empty() && !out.sunDegrees.empty()) {
        entry.fail("keys", "set both 'direction' and a sun position (azimuthDegrees, elevationDegrees)");
    }
    return out;
}

ScriptedMaterial parseMaterial(const nlohmann::json& value, const std::string& where, double framesPerSecond,
                               const std::filesystem::path& file) {
    const JsonObject entry(value, where, file, {"material", "interpolation", "keys"});
    ScriptedMaterial out;
    out.where = where;
    out.material = requiredName(entry, "material");
    out.emission.interpolation = interpolation(entry);
    out.on.interpolation = Interpolation::Step;
    std::optional<double> previous;
    forEachKey(entry, where, [&](const std::string& keyWhere, const nlohmann::json& keyValue) {
        const JsonObject key(keyValue, keyWhere, file, {"frame", "time", "emission", "on"});
        const double time = keyTime(key, framesPerSecond, previous);
        previous = time;
        if (const auto emission = key.vec3("emission")) {
            push(out.emission, time, nonNegative(key, "emission", *emission));
        }
        if (const auto on = key.boolean("on")) {
            push(out.on, time, *on ? 1.0f : 0.0f);
        }
    });
    return out;
}

// --- resolving names against the loaded scene -----------------------------------------------

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& where,
                       const std::string& problem) {
    throw SceneError(file, "'" + where + "' " + problem);
}

// The one element of `items` named `name`.
template <typename T>
uint32_t findNamed(const std::vector<T>& items, const std::string& name, const char* kind,
                   const std::filesystem::path& file, const std::string& where) {
    std::optional<uint32_t> found;
    std::string known;
    for (size_t i = 0; i < items.size(); ++i) {
        if (items[i].name == name) {
            if (found) {
                fail(file, where,
                     "names " + std::string(kind) + " '" + name +
                         "', but several have that name; an animated one needs a unique name");
            }
            found = uint32_t(i);
        }
        if (i < 12) {
            known += (known.empty() ? "" : ", ") + ("'" + items[i].name + "'");
        }
    }
    if (!found) {
        fail(file, where,
             "names " + std::string(kind) + " '" + name + "', but the scene has none of that name (" +
                 std::string(kind) + "s: " + (known.empty() ? "none" : known) +
                 (items.size() > 12 ? ", ..." : "") + ")");
    }
    return *found;
}

void resolveObject(const ScriptedObject& object, const std::filesystem::path& file, Scene& scene) {
    SceneAnimation& animation = scene.animation;
    const uint32_t index =
        findNamed(scene.instances, object.instance, "instance", file, object.where + ".instance");
    for (const uint32_t moved : animation.animatedInstances()) {
        if (moved == index) {
            fail(file, object.where + ".instance",
                 "names instance '" + object.instance +
                     "', which another path or a glTF animation already moves (one source per instance)");
        }
    }
    animation.instancePaths.push_back({.instance = index,
                                       .rest = scene.instances[index].transform,
                                       .pivot = object.pivot,
                                       .translation = object.translation,
                                       .rotation = object.rotation});
}

void resolveLight(const ScriptedLight& scripted, const std::filesystem::path& file, Scene& scene) {
    const uint32_t index = findNamed(scene.lights, scripted.light, "light", file, scripted.where + ".light");
    for (const LightPath& other : scene.animation.lightPaths) {
        if (other.light == index) {
            fail(file, scripted.where + ".light",
                 "names light '" + scripted.light +
                     "', which an earlier entry already animates (one entry per light)");
        }
    }
    const Light& light = scene.lights[index];
    const std::string type = lightTypeName(light.type);
    if (!scripted.position.empty() && light.type == LightType::Directional) {
        fail(file, scripted.where,
             "moves the position of directional light '" + light.name + "', which has none");
    }
    if ((!scripted.direction.empty() || !scripted.sunDegrees.empty()) && light.type == LightType::Point) {
        fail(file, scripted.where, "turns point light '" + light.name + "', which has no direction");
    }
    if (!scripted.sunDegrees.empty() && light.type != LightType::Directional) {
        fail(file, scripted.where,
             "gives " + type + " light '" + light.name +
                 "' a sun position; azimuth and elevation are for directional lights");
    }
    LightPath path{.light = index,
                   .restIntensity = light.intensity,
                   .position = scripted.position,
                   .direction = scripted.direction,
                   .sunDegrees = scripted.sunDegrees,
                   .color = scripted.color,
                   .intensity = scripted.intensity,
                   .on = scripted.on};
    if (light.type != LightType::Directional) {
        for (float& value : path.intensity.values) {
            value = float(pointIntensityFromCandela(value, scene.units.metresPerUnit));
            if (!std::isfinite(value)) {
                fail(file, scripted.where,
                     "gives light '" + light.name + "' an intensity that overflows in scene units");
            }
        }
    }
    scene.animation.lightPaths.push_back(std::move(path));
}

void resolveMaterial(const ScriptedMaterial& scripted, const std::filesystem::path& file, Scene& scene) {
    const uint32_t index =
        findNamed(scene.materials, scripted.material, "material", file, scripted.where + ".material");
    for (const MaterialPath& other : scene.animation.materialPaths) {
        if (other.material == index) {
            fail(file, scripted.where + ".material",
                 "names material '" + scripted.material +
                     "', which an earlier entry already animates (one entry per material)");
        }
    }
    scene.animation.materialPaths.push_back({.material = index,
                                             .restEmission = scene.materials[index].emission,
                                             .emission = scripted.emission,
                                             .on = scripted.on});
}

} // namespace

ScriptedAnimation parseScriptedAnimation(const nlohmann::json& value, double framesPerSecond,
                                         const std::filesystem::path& file) {
    const JsonObject root(value, "animation", file,
                          {"loopFrames", "loopSeconds", "objects", "lights", "sun", "materials"});
    ScriptedAnimation out;
    if (root.has("loopFrames") && root.has("loopSeconds")) {
        root.fail("loopFrames", "and 'animation.loopSeconds' cannot both be given");
    }
    if (const auto frames = root.unsignedInt("loopFrames", 1, std::numeric_limits<uint32_t>::max())) {
        out.loopSeconds = double(*frames) / framesPerSecond;
    }
    if (const auto seconds = root.number("loopSeconds")) {
        if (!(*seconds > 0.0) || *seconds > kMaxKeySeconds) {
            root.fail("loopSeconds", "must be in (0, " + std::to_string(kMaxKeySeconds) + "]");
        }
        out.loopSeconds = *seconds;
    }
    auto each = [&](std::string_view key, auto&& parse) {
        if (const nlohmann::json* entries = root.array(key)) {
            for (size_t i = 0; i < entries->size(); ++i) {
                parse((*entries)[i], root.path(key) + "[" + std::to_string(i) + "]");
            }
        }
    };
    each("objects", [&](const nlohmann::json& v, const std::string& where) {
        out.objects.push_back(parseObject(v, where, framesPerSecond, file));
    });
    each("lights", [&](const nlohmann::json& v, const std::string& where) {
        out.lights.push_back(parseLight(v, where, framesPerSecond, file, false));
    });
    if (const nlohmann::json* sun = root.object("sun")) {
        out.lights.push_back(parseLight(*sun, "animation.sun", framesPerSecond, file, true));
    }
    each("materials", [&](const nlohmann::json& v, const std::string& where) {
        out.materials.push_back(parseMaterial(v, where, framesPerSecond, file));
    });
    if (out.objects.empty() && out.lights.empty() && out.materials.empty()) {
        root.fail("objects", "(or 'lights', 'sun', 'materials'): the animation section animates nothing");
    }
    return out;
}

void resolveScriptedAnimation(const ScriptedAnimation& script, const std::filesystem::path& file,
                              Scene& scene) {
    for (const ScriptedObject& object : script.objects) {
        resolveObject(object, file, scene);
    }
    for (const ScriptedLight& light : script.lights) {
        resolveLight(light, file, scene);
    }
    for (const ScriptedMaterial& material : script.materials) {
        resolveMaterial(material, file, scene);
    }
    scene.animation.scriptLoopSeconds = script.loopSeconds;
}

} // namespace lumina::scene
