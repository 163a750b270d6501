#include "gi/scene/generators/two_room_layout.h"

#include "gi/scene/mesh_builder.h"

#include <algorithm>
#include <vector>

namespace lumina::scene::two_room {

namespace {

constexpr uint32_t kSkipBottom = 1u << 2, kSkipTop = 1u << 3, kSkipSouth = 1u << 4, kSkipNorth = 1u << 5;

} // namespace

// Watertight (MeshBuilder::roomFace): the floor, the ceiling and the walls are cut into a grid at the
// ceiling opening's edges. Before, a pixel of the west room's end wall seen through a seam in the
// dividing wall carried 16 % of `two_rooms`' relMSE at 128 x 128 (docs/gi.md, energy 26.).
Mesh shellMesh(const std::optional<CeilingOpening>& opening) {
    const glm::vec3 min(-kRoomLength - kHalfWall, 0.0f, -kHalfDepth),
        max(kRoomLength + kHalfWall, kHeight, kHalfDepth);
    std::vector<float> xs{min.x, max.x}, zs{min.z, max.z};
    if (opening) {
        xs = {min.x, opening->minX, opening->maxX, max.x};
        zs = {min.z, -opening->halfZ, opening->halfZ, max.z};
    }
    enum Face : uint32_t { kWest, kEast, kFloorFace, kCeiling, kSouth, kNorth };
    MeshBuilder rooms("rooms");
    rooms.material(kPlaster);
    for (const uint32_t face : {kSouth, kNorth, kEast}) {
        rooms.roomFace(min, max, xs, zs, face);
    }
    rooms.roomFace(min, max, xs, zs, kCeiling,
                   [&](size_t i, size_t k) { return opening && i == 1 && k == 1; });
    rooms.material(kFloor);
    rooms.roomFace(min, max, xs, zs, kFloorFace);
    rooms.material(kOchre);
    rooms.roomFace(min, max, xs, zs, kWest);
    return rooms.finish();
}

// The two pieces beside the doorway are cut at the lintel's height, so that their faces share the
// lintel's edges (no T-junction where the lintel meets them, above).
Mesh dividingWallMesh() {
    MeshBuilder wall("dividing wall");
    wall.material(kPlaster);
    for (const float side : {-1.0f, 1.0f}) {
        const float inner = side * kDoorwayHalfWidth, outer = side * kHalfDepth;
        // The face against the shell is left out; the one towards the doorway is the jamb below the
        // lintel's height and lies inside the lintel above it.
        const uint32_t shell = side < 0.0f ? kSkipSouth : kSkipNorth,
                       doorway = side < 0.0f ? kSkipNorth : kSkipSouth;
        wall.box({-kHalfWall, 0.0f, std::min(inner, outer)},
                 {kHalfWall, kDoorwayHeight, std::max(inner, outer)}, false, kSkipBottom | kSkipTop | shell);
        wall.box({-kHalfWall, kDoorwayHeight, std::min(inner, outer)},
                 {kHalfWall, kHeight, std::max(inner, outer)}, false,
                 kSkipBottom | kSkipTop | shell | doorway);
    }
    wall.box({-kHalfWall, kDoorwayHeight, -kDoorwayHalfWidth}, {kHalfWall, kHeight, kDoorwayHalfWidth}, false,
             kSkipTop | kSkipSouth | kSkipNorth);
    return wall.finish();
}

} // namespace lumina::scene::two_room
