// A closed room whose only opening is a square hole in its roof: the sun lights a patch of
// floor through it and everything else inside is lit indirectly.
#include "gi/scene/generators/generators.h"
#include "gi/scene/mesh_builder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

namespace lumina::scene {

namespace {

// Room 10 m x 4 m high x 10 m; the opening is 2 m x 2 m, off-centre so the sunlit patch
// is in view.
constexpr float kHalfWidth = 5.0f;
constexpr float kHeight = 4.0f;
constexpr float kHoleMinX = -1.5f, kHoleMaxX = 0.5f, kHoleMinZ = -0.5f, kHoleMaxZ = 1.5f;
// Sun illuminance (lux as radiometric irradiance, units.h) and sky radiance.
constexpr float kSunIlluminance = 20.0f;
constexpr glm::vec3 kSky{0.3f, 0.45f, 0.7f};

enum RoomMaterial : uint32_t { kWalls, kFloor, kRoof, kRedBlock, kBlueBlock };

} // namespace

Scene makeOpenTopBox() {
    Scene scene;
    scene.name = "open_top_box";
    scene.description = "closed room lit by the sun through a hole in its roof: nearly all light is indirect";
    scene.materials = {
        {.name = "walls", .baseColor = {0.8f, 0.8f, 0.8f, 1.0f}, .metallic = 0.0f, .doubleSided = true},
        {.name = "floor", .baseColor = {0.7f, 0.65f, 0.6f, 1.0f}, .metallic = 0.0f, .doubleSided = true},
        {.name = "roof", .baseColor = {0.5f, 0.5f, 0.5f, 1.0f}, .metallic = 0.0f, .doubleSided = true},
        {.name = "red block", .baseColor = {0.75f, 0.1f, 0.08f, 1.0f}, .metallic = 0.0f},
        {.name = "blue block", .baseColor = {0.1f, 0.2f, 0.7f, 1.0f}, .metallic = 0.0f},
    };

    MeshBuilder room("room");
    // Watertight (MeshBuilder::roomFace): walls, floor and roof cut into a grid at the opening's edges.
    const glm::vec3 min(-kHalfWidth, 0.0f, -kHalfWidth), max(kHalfWidth, kHeight, kHalfWidth);
    const std::vector<float> xs{-kHalfWidth, kHoleMinX, kHoleMaxX, kHalfWidth},
        zs{-kHalfWidth, kHoleMinZ, kHoleMaxZ, kHalfWidth};
    enum Face : uint32_t { kWestWall, kEastWall, kFloorFace, kRoofFace, kSouthWall, kNorthWall };
    room.material(kWalls);
    for (const uint32_t face : {kWestWall, kEastWall, kSouthWall, kNorthWall}) {
        room.roomFace(min, max, xs, zs, face);
    }
    room.material(kFloor);
    room.roomFace(min, max, xs, zs, kFloorFace);
    room.material(kRoof);
    room.roomFace(min, max, xs, zs, kRoofFace, [](size_t i, size_t k) { return i == 1 && k == 1; });
    scene.meshes.push_back(room.finish());

    MeshBuilder block("block");
    block.box({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, false, /*skip bottom*/ 1u << 2);
    Mesh blockMesh = block.finish();
    blockMesh.submeshes[0].material = kRedBlock;
    scene.meshes.push_back(blockMesh);
    blockMesh.name = "tall block";
    blockMesh.submeshes[0].material = kBlueBlock;
    scene.meshes.push_back(blockMesh);

    scene.instances.push_back({.mesh = 0, .transform = glm::mat4(1.0f), .name = "room"});
    glm::mat4 red = glm::translate(glm::mat4(1.0f), {2.2f, 0.0f, 2.0f});
    red = glm::rotate(red, glm::radians(20.0f), {0.0f, 1.0f, 0.0f});
    scene.instances.push_back({.mesh = 1, .transform = red, .name = "red block"});
    glm::mat4 blue = glm::translate(glm::mat4(1.0f), {-2.5f, 0.0f, 2.8f});
    blue = glm::rotate(blue, glm::radians(-15.0f), {0.0f, 1.0f, 0.0f});
    blue = glm::scale(blue, {1.0f, 2.2f, 1.0f});
    scene.instances.push_back({.mesh = 2, .transform = blue, .name = "blue block"});

    scene.lights.push_back({.type = LightType::Directional,
                            .name = "sun",
                            .intensity = kSunIlluminance,
                            .direction = glm::normalize(glm::vec3(0.25f, -1.0f, 0.3f))});
    scene.camera = {.name = "camera",
                    .position = {-4.3f, 1.7f, -4.3f},
                    .forward = glm::normalize(glm::vec3(1.0f, -0.2f, 1.0f)),
                    .fovY = glm::radians(70.0f),
                    .nearPlane = 0.05f,
                    .farPlane = 50.0f};
    scene.camera.up = glm::normalize(
        glm::cross(glm::cross(scene.camera.forward, glm::vec3(0.0f, 1.0f, 0.0f)), scene.camera.forward));
    scene.cameraFromFile = true;
    scene.sky = kSky;
    scene.image = {1280, 720};
    return scene;
}

} // namespace lumina::scene
