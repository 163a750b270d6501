// `lumina info SCENE`: loads a scene (a built-in's name or a path) and prints what it holds:
// counts, bounds, camera, units, lights and every repair the loader made. Needs no GPU.
#include "app/command.h"
#include "app/commands/scene_options.h"
#include "gi/frame/gi_technique.h"
#include "gi/scene/animation_summary.h"
#include "gi/scene/builtin_scenes.h"
#include "gi/scene/generators/generators.h"
#include "gi/scene/scene_loader.h"
#include "gi/surface_cache/surface_cards.h"

#include <chrono>
#include <cstdio>
#include <glm/glm.hpp>
#include <iostream>
#include <sstream>
#include <string>

namespace lumina::app {

namespace {

// Repair warnings printed before the rest is summarised.
constexpr size_t kMaxWarningsShown = 20;

std::string format(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", value == 0.0 ? 0.0 : value); // no "-0"
    return text;
}

std::string format(const glm::vec3& v) {
    return "(" + format(v.x) + ", " + format(v.y) + ", " + format(v.z) + ")";
}

void printRow(const char* label, const std::string& value) {
    std::printf("  %-12s %s\n", label, value.c_str());
}

std::string lightLine(const scene::Light& light) {
    std::string line = std::string(scene::lightTypeName(light.type)) + " '" + light.name + "' ";
    switch (light.type) {
    case scene::LightType::Directional:
        line += "travelling " + format(light.direction) + ", irradiance " + format(light.strength());
        break;
    case scene::LightType::Point:
        line += "at " + format(light.position) + ", intensity " + format(light.strength());
        break;
    case scene::LightType::Spot:
        line += "at " + format(light.position) + " towards " + format(light.direction) + ", intensity " +
                format(light.strength()) + ", cone " + format(glm::degrees(light.innerConeAngle)) + "-" +
                format(glm::degrees(light.outerConeAngle)) + " deg";
        break;
    }
    if (light.range > 0.0f) {
        line += ", range " + format(light.range);
    }
    return line;
}

// The surface cache lumen would build for the scene camera's view (CPU only): atlas occupancy
// and the cards at each level of detail.
void printSurfaceCache(const scene::Scene& loaded, const std::string& presetName) {
    gi::LumenSettings lumen;
    try {
        lumen = gi::lumenPreset(presetName, loaded);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    const surface_cache::SurfaceCards cards(loaded, lumen.cache);
    printRow("surface cache", "preset " + presetName + ", atlas " + std::to_string(lumen.cache.atlasSize) +
                                  "^2 from the camera: " + surface_cache::toString(cards.occupancy()));
}

int runInfo(const ParsedArgs& args) {
    if (args.positional.size() != 1) {
        throw UsageError(
            "info takes one scene: a built-in name or a .json, .gltf or .glb path (see lumina info "
            "--help)");
    }
    scene::LoadOptions options = sceneLoadOptions(args);
    if (args.has("instances")) {
        options.instances = uint32_t(args.getUint("instances", 0, 1, scene::kCityMaxBuildings));
    }
    const std::string& name = args.positional.front();
    const auto start = std::chrono::steady_clock::now();
    scene::Scene loaded = scene::loadScene(name, options);
    const double milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (args.common.size) {
        loaded.image = {args.common.size->width, args.common.size->height};
    }

    uint64_t emissive = 0, texels = 0;
    for (const scene::Material& material : loaded.materials) {
        emissive += glm::any(glm::greaterThan(material.emission, glm::vec3(0.0f))) ? 1 : 0;
    }
    for (const scene::Texture& texture : loaded.textures) {
        texels += uint64_t(texture.width) * texture.height;
    }
    uint32_t byType[3] = {0, 0, 0};
    for (const scene::Light& light : loaded.lights) {
        ++byType[int(light.type)];
    }
    const scene::Bounds bounds = loaded.worldBounds();
    const scene::Camera& camera = loaded.camera;

    std::printf("scene %s%s\n", loaded.name.c_str(), scene::isBuiltinScene(name) ? " (built-in)" : "");
    printRow("file", loaded.sourceFile.generic_string());
    printRow("source", loaded.generator.empty() ? "glTF " + loaded.gltfFile.generic_string()
                                                : "generator " + loaded.generator);
    if (!loaded.description.empty()) {
        printRow("description", loaded.description);
    }
    printRow("triangles", std::to_string(loaded.triangleCount()) + " drawn, " +
                              std::to_string(loaded.meshTriangleCount()) + " in meshes");
    printRow("vertices", std::to_string(loaded.vertexCount()));
    printRow("meshes", std::to_string(loaded.meshes.size()));
    printRow("instances", std::to_string(loaded.instances.size()));
    printRow("materials",
             std::to_string(loaded.materials.size()) + " (" + std::to_string(emissive) + " emissive)");
    printRow("textures", std::to_string(loaded.textures.size()) + " (" + std::to_string(texels) + " texels)");
    printRow("lights", std::to_string(loaded.lights.size()) + " (" + std::to_string(byType[0]) +
                           " directional, " + std::to_string(byType[1]) + " point, " +
                           std::to_string(byType[2]) + " spot)");
    for (const scene::Light& light : loaded.lights) {
        printRow("", lightLine(light));
    }
    printRow("bounds", format(bounds.min) + " to " + format(bounds.max) + ", size " + format(bounds.size()));
    printRow("camera", "'" + camera.name + "' at " + format(camera.position) + " looking " +
                           format(camera.forward) + " up " + format(camera.up) +
                           (loaded.cameraFromFile ? "" : " (framed to the bounds)"));
    printRow("", "vertical fov " + format(glm::degrees(camera.fovY)) + " deg, near " +
                     format(camera.nearPlane) + ", far " + format(camera.farPlane));
    printRow("units", format(loaded.units.metresPerUnit) + " m per scene unit");
    printRow("sky", loaded.skyEnvironment
                        ? "environment " + loaded.skyEnvironment->file.generic_string() + " (" +
                              std::to_string(loaded.skyEnvironment->width) + "x" +
                              std::to_string(loaded.skyEnvironment->height) + ", intensity " +
                              format(loaded.skyEnvironment->intensity) + ")"
                        : "radiance " + format(loaded.sky));
    printRow("", lightingLine(loaded));
    printRow("image", std::to_string(loaded.image.width) + "x" + std::to_string(loaded.image.height) +
                          (args.common.size ? " (from --size)" : ""));
    const std::vector<std::string> animation = scene::animationSummary(loaded);
    for (size_t i = 0; i < animation.size(); ++i) {
        printRow(i == 0 ? "animation" : "", animation[i]);
    }
    printRow("technique", loaded.technique.empty() ? "(renderer default)" : loaded.technique);
    printRow("preset", loaded.preset.empty() ? "(renderer default)" : loaded.preset);
    printRow("load time", format(milliseconds) + " ms");
    printSurfaceCache(loaded, args.get("preset", loaded.preset.empty() ? gi::kDefaultPreset : loaded.preset));

    const scene::LoadReport& report = loaded.report;
    printRow("repairs",
             std::to_string(report.degenerateTrianglesDropped) + " degenerate triangles dropped, " +
                 std::to_string(report.nonTrianglePrimitivesSkipped) + " point/line primitives skipped, " +
                 std::to_string(report.normalsRepaired) + " normals regenerated");
    for (size_t i = 0; i < report.warnings.size() && i < kMaxWarningsShown; ++i) {
        printRow("warning", report.warnings[i]);
    }
    if (report.warnings.size() > kMaxWarningsShown) {
        printRow("warning",
                 "... and " + std::to_string(report.warnings.size() - kMaxWarningsShown) + " more");
    }
    return 0;
}

} // namespace

Command infoCommand() {
    std::string builtins;
    for (const scene::BuiltinScene& builtin : scene::builtinScenes()) {
        builtins += (builtins.empty() ? "" : ", ") + std::string(builtin.name);
    }
    static const std::string description =
        "Loads SCENE and prints its triangle, vertex, mesh, instance, material, texture and light counts, "
        "its bounds, camera, units, sky, image size, animation (tracks, what they move, loop length), GI "
        "technique and preset, the load time, the surface cache's "
        "atlas occupancy and cards per level of detail from the scene camera, and every repair the "
        "loader made. SCENE is a built-in scene (" +
        builtins +
        ") or a path to a scene file (.json), .gltf or .glb. Bad input is an error naming the file and the "
        "problem (exit code 1). docs/scenes.md describes scene files and units.";
    return {.name = "info",
            .summary = "load a scene and print what it holds",
            .usage =
                "lumina info SCENE [--instances N] [--size WxH] [--preset P] [--no-default-light] [--sky "
                "FILE.exr [--sky-intensity K]]",
            .description = description,
            .flags = withSceneLoadFlags(
                {{"instances", "N", "building count of a generated city (default 1024)"},
                 {"preset", "P",
                  "the GI preset whose surface cache to describe (low, medium, high; default the "
                  "scene's, else medium)"}}),
            .run = runInfo};
}

} // namespace lumina::app
