// Two rooms side by side under one roof, joined by a doorway in the wall between them: the west
// room (x < 0) is lit by a lamp, the east room (x > 0), where the camera stands, has no light of
// its own. A door on the east side of the doorway, hinged at its south edge, closes it; the
// scene file (scenes/door/door.json) swings it open about that hinge and back, so all the light
// the camera sees arrives through the doorway, indirectly. Metres, y up.
#include "gi/scene/generators/generators.h"
#include "gi/scene/generators/two_room_layout.h"
#include "gi/scene/mesh_builder.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lumina::scene {

namespace {

// The door: 4 cm thick, `gap` (1 cm by default) off the east face of the wall, overlapping the
// doorway by 6 cm at the sides and 5 cm at the top so that no straight ray slips past it when closed.
constexpr float kDoorThickness = 0.04f, kDoorOverlap = 0.06f, kDoorHeight = 2.15f;
// The lamp (point light), in candela = scene intensity in metres (units.h): about 3.7 lux on
// the floor below it.
constexpr float kLampCandela = 25.0f;

using namespace two_room;

constexpr uint32_t kWood = kFirstOwnMaterial;
constexpr uint32_t kSkipBottom = 1u << 2;

Mesh doorMesh(float gap) {
    MeshBuilder door("door");
    door.material(kWood);
    const float x0 = kHalfWall + gap, halfWidth = kDoorwayHalfWidth + kDoorOverlap;
    door.box({x0, 0.0f, -halfWidth}, {x0 + kDoorThickness, kDoorHeight, halfWidth}, false, kSkipBottom);
    return door.finish();
}

} // namespace

glm::vec3 doorHinge(float gap) {
    return {kHalfWall + gap + kDoorThickness, 0.0f, -(kDoorwayHalfWidth + kDoorOverlap)};
}

Scene makeDoor(float gap) {
    Scene scene;
    scene.name = "door";
    scene.description = "a lit room and a dark one joined by a doorway; the door swings open and shut";
    scene.materials = {
        {.name = "plaster", .baseColor = {0.78f, 0.76f, 0.72f, 1.0f}},
        {.name = "floor", .baseColor = {0.45f, 0.4f, 0.35f, 1.0f}},
        {.name = "ochre", .baseColor = {0.8f, 0.5f, 0.15f, 1.0f}},
        {.name = "wood", .baseColor = {0.5f, 0.32f, 0.18f, 1.0f}},
    };
    scene.meshes = {shellMesh(), dividingWallMesh(), doorMesh(gap)};
    for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
        scene.instances.push_back({.mesh = i, .transform = glm::mat4(1.0f), .name = scene.meshes[i].name});
    }
    scene.lights.push_back({.type = LightType::Point,
                            .name = "lamp",
                            .intensity = kLampCandela,
                            .position = {-0.5f * kRoomLength - kHalfWall, kHeight - 0.4f, 0.0f}});
    // In the dark room's far corner, looking back at the doorway and the door's swing.
    scene.camera = {.name = "camera",
                    .position = {3.6f, 1.6f, 1.6f},
                    .forward = glm::normalize(glm::vec3(0.1f, 1.0f, -0.3f) - glm::vec3(3.6f, 1.6f, 1.6f)),
                    .fovY = glm::radians(60.0f),
                    .nearPlane = 0.05f,
                    .farPlane = 30.0f};
    scene.camera.up = glm::normalize(
        glm::cross(glm::cross(scene.camera.forward, glm::vec3(0.0f, 1.0f, 0.0f)), scene.camera.forward));
    scene.cameraFromFile = true;
    scene.sky = glm::vec3(0.0f);
    scene.image = {960, 540};
    return scene;
}

} // namespace lumina::scene
