#include "app/viewer/viewer_settings.h"

#include "app/viewer/viewer_options.h"
#include "gi/frame/gi_technique.h"
#include "gi/frame/preset.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <system_error>

namespace lumina::app::viewer {

namespace {

using Json = nlohmann::json;

bool scripted(const ViewerOptions& options) {
    return options.common.frames || options.screenshotAfter || options.testResize || options.testEdits ||
           options.cycleViews || !options.testHotReload.empty();
}

Json vec3Json(const glm::vec3& v) {
    return Json::array({v.x, v.y, v.z});
}

glm::vec3 vec3(const Json& json, const char* name) {
    const Json& value = json.at(name);
    if (!value.is_array() || value.size() != 3) {
        throw std::runtime_error(std::string("'") + name + "' is not an array of 3 numbers");
    }
    const glm::vec3 v(value[0].get<float>(), value[1].get<float>(), value[2].get<float>());
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
        throw std::runtime_error(std::string("'") + name + "' is not finite");
    }
    return v;
}

scene::Camera cameraFrom(const Json& json) {
    scene::Camera camera;
    camera.position = vec3(json, "position");
    camera.forward = vec3(json, "forward");
    camera.up = vec3(json, "up");
    camera.fovY = json.at("fovY").get<float>();
    camera.nearPlane = json.at("near").get<float>();
    camera.farPlane = json.at("far").get<float>();
    const bool degenerate = glm::length(camera.forward) < 1e-6f || glm::length(camera.up) < 1e-6f ||
                            glm::length(glm::cross(camera.forward, camera.up)) < 1e-6f;
    if (degenerate || !(camera.fovY > 0.0f && camera.fovY < 3.14f) || !(camera.nearPlane > 0.0f) ||
        !(camera.farPlane > camera.nearPlane) || !std::isfinite(camera.farPlane)) {
        throw std::runtime_error("the camera is not a valid one");
    }
    camera.forward = glm::normalize(camera.forward);
    camera.up = glm::normalize(camera.up);
    return camera;
}

// A technique or preset this build does not know is dropped with a note, not an error.
std::string known(const Json& json, const char* name, const std::filesystem::path& path) {
    if (!json.contains(name)) {
        return {};
    }
    const std::string value = json.at(name).get<std::string>();
    try {
        if (std::string_view(name) == "technique") {
            gi::parseGiTechnique(value);
        } else {
            gi::findPreset(value);
        }
    } catch (const std::invalid_argument& e) {
        std::cerr << "lumina-viewer: settings " << path.string() << ": " << name << " '" << value
                  << "' skipped: " << e.what() << '\n';
        return {};
    }
    return value;
}

} // namespace

std::optional<std::filesystem::path> viewerSettingsPath(const ViewerOptions& options) {
    if (!options.settingsPath.empty()) {
        return options.settingsPath;
    }
    if (scripted(options)) {
        return std::nullopt;
    }
    if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config) {
        return std::filesystem::path(config) / "lumina" / "viewer.json";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return std::filesystem::path(home) / ".config" / "lumina" / "viewer.json";
    }
    return std::nullopt;
}

std::optional<ViewerSettings> loadViewerSettings(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) {
        return std::nullopt; // the first run: nothing saved yet
    }
    try {
        const Json json = Json::parse(in);
        ViewerSettings settings;
        settings.scene = json.value("scene", std::string());
        settings.technique = known(json, "technique", path);
        settings.preset = known(json, "preset", path);
        settings.exposureEv = json.value("exposureEv", 0.0f);
        if (!std::isfinite(settings.exposureEv)) {
            settings.exposureEv = 0.0f;
        }
        settings.vsync = json.value("vsync", true);
        settings.view = json.value("view", std::string());
        if (json.contains("camera")) {
            settings.camera = cameraFrom(json.at("camera"));
        }
        return settings;
    } catch (const std::exception& e) {
        std::cerr << "lumina-viewer: settings " << path.string() << " skipped: " << e.what() << '\n';
        return std::nullopt;
    }
}

void applySavedSettings(const ViewerSettings& saved, ViewerOptions& options) {
    if (options.technique.empty()) {
        options.technique = saved.technique;
    }
    if (options.preset.empty()) {
        options.preset = saved.preset;
    }
    if (!options.exposureSet) {
        options.exposureEv = saved.exposureEv;
    }
    if (!options.vsyncSet) {
        options.vsync = saved.vsync;
    }
    if (options.view.empty() && !saved.view.empty()) {
        options.view = saved.view;
        options.viewFromSettings = true;
    }
    if (saved.scene == options.scene && saved.camera) {
        options.camera = saved.camera;
    }
}

void saveViewerSettings(const std::filesystem::path& path, const ViewerSettings& settings) {
    Json json = {{"scene", settings.scene},   {"technique", settings.technique},
                 {"preset", settings.preset}, {"exposureEv", settings.exposureEv},
                 {"vsync", settings.vsync},   {"view", settings.view}};
    if (settings.camera) {
        const scene::Camera& camera = *settings.camera;
        json["camera"] = {{"position", vec3Json(camera.position)},
                          {"forward", vec3Json(camera.forward)},
                          {"up", vec3Json(camera.up)},
                          {"fovY", camera.fovY},
                          {"near", camera.nearPlane},
                          {"far", camera.farPlane}};
    }
    std::error_code error;
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path(), error);
    }
    std::filesystem::path temporary = path;
    temporary += ".tmp";
    {
        std::ofstream out(temporary, std::ios::trunc);
        out << json.dump(2) << '\n';
        if (!out) {
            throw std::runtime_error("cannot write the viewer's settings to " + temporary.string());
        }
    }
    std::filesystem::rename(temporary, path, error);
    if (error) {
        throw std::runtime_error("cannot write the viewer's settings to " + path.string() + ": " +
                                 error.message());
    }
}

} // namespace lumina::app::viewer
