#pragma once
// The layout the `door`, `two_rooms` and `sunlit_rooms` generators share: two rooms side by side
// under one roof, joined by a doorway in the wall between them (west room x < 0, east room x > 0).
// Metres, y up.
#include "gi/scene/scene.h"

#include <cstdint>
#include <optional>

namespace lumina::scene::two_room {

// Each room 4 m x 3 m high x 4 m; the wall between them is 0.2 m thick, centred on x = 0.
inline constexpr float kRoomLength = 4.0f, kHeight = 3.0f, kHalfDepth = 2.0f, kHalfWall = 0.1f;
// The doorway: 1 m wide (z in [-0.5, 0.5]), 2.1 m high.
inline constexpr float kDoorwayHalfWidth = 0.5f, kDoorwayHeight = 2.1f;

// Material indices the meshes below use; a generator's own materials follow them.
enum Material : uint32_t { kPlaster, kFloor, kOchre, kFirstOwnMaterial };

// A rectangle of the ceiling left open (x in [minX, maxX], z in [-halfZ, halfZ]).
struct CeilingOpening {
    float minX, maxX, halfZ;
};

// The shell around both rooms, facing in: plaster walls and ceiling (less `opening`), its own
// floor, and the west room's end wall ochre (the colour the bounced light carries east).
Mesh shellMesh(const std::optional<CeilingOpening>& opening = std::nullopt);
// The wall between the rooms: two full-height pieces beside the doorway and a lintel above it,
// without the faces that touch the shell or each other (a solid: docs/sdf.md).
Mesh dividingWallMesh();

} // namespace lumina::scene::two_room
