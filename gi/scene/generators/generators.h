#pragma once
// The code that makes Lumina's built-in scenes. The small ones (Cornell box, open-top box,
// furnaces) are written once to scenes/<name>/ as glTF + scene file and loaded from there;
// atrium, city and door are generated each time their scene file is loaded.
#include "gi/scene/scene.h"

#include <cstdint>
#include <string_view>

namespace lumina::scene {

// The Cornell box after the published data (millimetres); `pointLight` swaps the light quad
// for a point light of the same total power.
Scene makeCornellBox(bool pointLight);

// A closed room lit only through an opening in its roof.
Scene makeOpenTopBox();

// The inside of a closed box whose every surface has albedo `albedo` and emits radiance 1:
// its exact radiance is 1 / (1 - albedo) everywhere.
Scene makeFurnace(float albedo);

// A courtyard with two storeys of arcades, columns, coloured drapes and a sun (metres).
Scene makeAtrium();

// Two rooms joined by a doorway, one lit by a lamp, the other (with the camera) dark, and a
// door that scenes/door/door.json swings about doorHinge() (metres). `gap`: between the shut door
// and the wall (scene-file key `doorGap`), within [kDoorMinGap, kDoorMaxGap].
inline constexpr float kDoorDefaultGap = 0.01f, kDoorMinGap = 0.001f, kDoorMaxGap = 0.5f;
Scene makeDoor(float gap = kDoorDefaultGap);
// A point on the axis of the hinge of the door `gap` off the wall (vertical, through this point).
glm::vec3 doorHinge(float gap = kDoorDefaultGap);

// Two rooms joined by a doorway, only the west one lit, the camera in the east one (metres):
// by an emissive panel in the west room's ceiling (two_rooms), or by the sun and sky through an
// opening there (sunlit_rooms).
Scene makeTwoRooms();
Scene makeSunlitRooms();

// A grid of `buildings` instanced buildings on a ground plane (metres).
inline constexpr uint32_t kCityDefaultBuildings = 1024;
inline constexpr uint32_t kCityMaxBuildings = 1u << 20;
Scene makeCity(uint32_t buildings);

} // namespace lumina::scene
