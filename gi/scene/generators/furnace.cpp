// Furnace scenes: a closed room, every surface of albedo rho emitting radiance Le = 1. In
// any closed enclosure of uniform albedo and emission the radiance leaving each point is
// L = Le + rho L (it sees only such surfaces), so L = Le / (1 - rho) everywhere, whatever
// the geometry: the block inside only adds occlusion for the GI to get right.
#include "gi/scene/generators/generators.h"
#include "gi/scene/mesh_builder.h"

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

namespace lumina::scene {

namespace {

// Half the room's side, metres.
constexpr float kHalfSide = 2.0f;
constexpr float kBlockSide = 0.8f;
constexpr float kEmission = 1.0f;

} // namespace

Scene makeFurnace(float albedo) {
    char name[32];
    std::snprintf(name, sizeof(name), "furnace_%g", double(albedo));
    Scene scene;
    scene.name = name;
    char description[128];
    std::snprintf(
        description, sizeof(description),
        "closed box of albedo %g emitting radiance 1 on every surface: exact radiance %g everywhere",
        double(albedo), 1.0 / (1.0 - double(albedo)));
    scene.description = description;
    scene.materials = {{.name = "furnace",
                        .baseColor = glm::vec4(glm::vec3(albedo), 1.0f),
                        .emission = glm::vec3(kEmission),
                        .metallic = 0.0f}};

    MeshBuilder room("room");
    room.box(glm::vec3(-kHalfSide), glm::vec3(kHalfSide), /*inward=*/true);
    scene.meshes.push_back(room.finish());
    MeshBuilder block("block");
    block.box(glm::vec3(-0.5f * kBlockSide), glm::vec3(0.5f * kBlockSide));
    scene.meshes.push_back(block.finish());

    scene.instances.push_back({.mesh = 0, .transform = glm::mat4(1.0f), .name = "room"});
    // The block stands on the floor, turned 30 degrees about y.
    glm::mat4 blockTransform = glm::translate(glm::mat4(1.0f), {0.5f, -kHalfSide + 0.5f * kBlockSide, 0.6f});
    blockTransform = glm::rotate(blockTransform, glm::radians(30.0f), {0.0f, 1.0f, 0.0f});
    scene.instances.push_back({.mesh = 1, .transform = blockTransform, .name = "block"});

    scene.camera = {.name = "camera",
                    .position = {-0.8f, 0.2f, -1.6f},
                    .forward = glm::normalize(glm::vec3(0.45f, -0.35f, 1.0f)),
                    .fovY = glm::radians(70.0f),
                    .nearPlane = 0.01f,
                    .farPlane = 20.0f};
    scene.camera.up = glm::normalize(
        glm::cross(glm::cross(scene.camera.forward, glm::vec3(0.0f, 1.0f, 0.0f)), scene.camera.forward));
    scene.cameraFromFile = true;
    scene.image = {256, 256};
    return scene;
}

} // namespace lumina::scene
