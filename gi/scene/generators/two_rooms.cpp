// Two rooms side by side under one roof, joined by a doorway in the 0.2 m wall between them.
// Only the west room (x < 0) receives light: in `two_rooms` from an emissive panel set in its
// ceiling, in `sunlit_rooms` from the sun and sky through an opening in its ceiling. The camera
// stands in the east room, so everything it sees but a patch of floor by the doorway is lit only
// by light that bounced at least once in the west room: the case that tests how much energy
// the GI carries over several bounces. Metres, y up.
#include "gi/scene/generators/generators.h"
#include "gi/scene/generators/two_room_layout.h"
#include "gi/scene/mesh_builder.h"

namespace lumina::scene {

namespace {

using namespace two_room;

// The ceiling opening of the west room (the panel, or the skylight): 1.2 m square, 2.6 m from
// the doorway so that the panel lights the east room directly only through the doorway.
constexpr float kOpeningMinX = -3.2f, kOpeningMaxX = -2.0f, kOpeningHalfZ = 0.6f;
constexpr CeilingOpening kOpening{kOpeningMinX, kOpeningMaxX, kOpeningHalfZ};
// The panel's radiance (downwards only): 80 x pi x 1.44 m^2 = 360 W, so that the camera's view
// reads about as bright as the Cornell box's (mean radiance about 0.3).
constexpr glm::vec3 kPanelRadiance{80.0f, 72.0f, 64.0f};
// Sun illuminance (lux as radiometric irradiance, units.h), its direction (onto the west room's
// floor, away from the doorway) and the sky radiance: the shaded room's mean radiance in the
// camera's view is about 0.08.
constexpr float kSunIlluminance = 150.0f;
constexpr glm::vec3 kSunDirection{0.2f, -1.0f, 0.25f};
constexpr glm::vec3 kSky{1.2f, 1.8f, 2.8f};

constexpr uint32_t kPanel = kFirstOwnMaterial;

// The panel fills the ceiling's opening, emitting downwards only.
Mesh panelMesh() {
    MeshBuilder panel("panel");
    panel.material(kPanel);
    panel.quad({kOpeningMinX, kHeight, -kOpeningHalfZ}, {kOpeningMaxX, kHeight, -kOpeningHalfZ},
               {kOpeningMaxX, kHeight, kOpeningHalfZ}, {kOpeningMinX, kHeight, kOpeningHalfZ});
    return panel.finish();
}

Scene twoRoomsScene(bool sunlit) {
    Scene scene;
    scene.name = sunlit ? "sunlit_rooms" : "two_rooms";
    scene.description =
        sunlit ? "a room sunlit through its ceiling and a shaded one behind a doorway, seen from "
                 "the shaded one"
               : "a room lit by a ceiling panel and a dark one behind a doorway, seen from the "
                 "dark one";
    // Double-sided where the sun meets the shell's outside, so that it casts the shadow.
    scene.materials = {
        {.name = "plaster", .baseColor = {0.78f, 0.76f, 0.72f, 1.0f}, .doubleSided = sunlit},
        {.name = "floor", .baseColor = {0.45f, 0.4f, 0.35f, 1.0f}, .doubleSided = sunlit},
        {.name = "ochre", .baseColor = {0.8f, 0.5f, 0.15f, 1.0f}, .doubleSided = sunlit},
    };
    scene.meshes = {shellMesh(kOpening), dividingWallMesh()};
    if (sunlit) {
        scene.lights.push_back({.type = LightType::Directional,
                                .name = "sun",
                                .intensity = kSunIlluminance,
                                .direction = glm::normalize(kSunDirection)});
        scene.sky = kSky;
    } else {
        scene.materials.push_back(
            {.name = "panel", .baseColor = {0.0f, 0.0f, 0.0f, 1.0f}, .emission = kPanelRadiance});
        scene.meshes.push_back(panelMesh());
        scene.sky = glm::vec3(0.0f);
    }
    for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
        scene.instances.push_back({.mesh = i, .transform = glm::mat4(1.0f), .name = scene.meshes[i].name});
    }
    // In the east room's far corner, looking back at the doorway.
    const glm::vec3 eye(3.7f, 1.6f, 1.7f), target(0.1f, 1.0f, -0.3f);
    scene.camera = {.name = "camera",
                    .position = eye,
                    .forward = glm::normalize(target - eye),
                    .fovY = glm::radians(60.0f),
                    .nearPlane = 0.05f,
                    .farPlane = 30.0f};
    scene.camera.up = glm::normalize(
        glm::cross(glm::cross(scene.camera.forward, glm::vec3(0.0f, 1.0f, 0.0f)), scene.camera.forward));
    scene.cameraFromFile = true;
    scene.image = {512, 512};
    return scene;
}

} // namespace

Scene makeTwoRooms() {
    return twoRoomsScene(false);
}

Scene makeSunlitRooms() {
    return twoRoomsScene(true);
}

} // namespace lumina::scene
