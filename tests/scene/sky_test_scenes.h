#pragma once
// Scenes and skies for the sky tests (path tracer, screen probes, surface-cache radiosity): a
// floor open to the sky, built in code, and latitude-longitude environments made in memory.
#include "gi/scene/scene.h"

#include <cstdint>
#include <string>

namespace lumina::test {

// A 2 m x 2 m floor at y = 0 facing +y, seen from 2.5 m above looking down (60 degrees
// vertical field of view); a black uniform sky and no light until the test adds one.
inline scene::Scene makeFloorScene(uint32_t imageSize, glm::vec3 albedo = glm::vec3(0.8f)) {
    scene::Scene scene;
    scene.name = "floor";
    scene::Mesh mesh;
    mesh.name = "floor";
    mesh.positions = {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}; // counter-clockwise from +y
    mesh.normals.assign(4, glm::vec3(0, 1, 0));
    mesh.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.submeshes = {{0, 6, 0}};
    for (const glm::vec3& p : mesh.positions) {
        mesh.bounds.extend(p);
    }
    scene.meshes.push_back(mesh);
    scene.instances.push_back({0, glm::mat4(1.0f), "floor"});
    scene::Material material;
    material.name = "grey";
    material.baseColor = glm::vec4(albedo, 1.0f);
    scene.materials.push_back(material);
    scene.camera.position = {0.0f, 2.5f, 0.0f};
    scene.camera.forward = {0.0f, -1.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.fovY = glm::radians(60.0f);
    scene.camera.nearPlane = 0.1f;
    scene.camera.farPlane = 10.0f;
    scene.image = {imageSize, imageSize};
    return scene;
}

// An environment of `width` x `height` texels made in memory: texel (x, y) is value(x, y).
template <typename Value>
scene::SkyEnvironment makeEnvironment(const std::string& name, uint32_t width, uint32_t height, Value value) {
    scene::SkyEnvironment sky;
    sky.file = name + " (in memory)";
    sky.width = width;
    sky.height = height;
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            sky.radiance.push_back(value(x, y));
        }
    }
    return sky;
}

// `top` over the upper hemisphere (rows above the middle: towards +y), `bottom` below.
// top == bottom makes a constant environment.
inline scene::SkyEnvironment twoHemisphereSky(glm::vec3 top, glm::vec3 bottom, uint32_t width = 32,
                                              uint32_t height = 64) {
    return makeEnvironment("two hemispheres", width, height,
                           [&](uint32_t, uint32_t y) { return y < height / 2 ? top : bottom; });
}

} // namespace lumina::test
