#include "gi/scene/generators/two_room_layout.h"

#include "gi/scene/mesh_builder.h"

namespace lumina::scene::two_room {

namespace {

constexpr uint32_t kSkipMinusX = 1u << 0, kSkipBottom = 1u << 2, kSkipTop = 1u << 3, kSkipSouth = 1u << 4,
                   kSkipNorth = 1u << 5;

} // namespace

Mesh shellMesh(const std::optional<CeilingOpening>& opening) {
    MeshBuilder rooms("rooms");
    rooms.material(kPlaster);
    const glm::vec3 min(-kRoomLength - kHalfWall, 0.0f, -kHalfDepth),
        max(kRoomLength + kHalfWall, kHeight, kHalfDepth);
    rooms.box(min, max, /*inward=*/true, kSkipMinusX | kSkipBottom | (opening ? kSkipTop : 0u));
    if (opening) {
        const auto ceiling = [&](float x0, float z0, float x1, float z1) {
            rooms.quad({x0, kHeight, z0}, {x1, kHeight, z0}, {x1, kHeight, z1},
                       {x0, kHeight, z1}); // facing down
        };
        ceiling(min.x, min.z, max.x, -opening->halfZ);
        ceiling(min.x, opening->halfZ, max.x, max.z);
        ceiling(min.x, -opening->halfZ, opening->minX, opening->halfZ);
        ceiling(opening->maxX, -opening->halfZ, max.x, opening->halfZ);
    }
    rooms.material(kFloor);
    rooms.quad({min.x, 0.0f, min.z}, {min.x, 0.0f, max.z}, {max.x, 0.0f, max.z}, {max.x, 0.0f, min.z});
    rooms.material(kOchre);
    rooms.quadFacingAwayFrom({min.x, 0.0f, min.z}, {min.x, 0.0f, max.z}, {min.x, kHeight, max.z},
                             {min.x, kHeight, min.z}, {min.x - 1.0f, 0.5f * kHeight, 0.0f});
    return rooms.finish();
}

Mesh dividingWallMesh() {
    MeshBuilder wall("dividing wall");
    wall.material(kPlaster);
    wall.box({-kHalfWall, 0.0f, -kHalfDepth}, {kHalfWall, kHeight, -kDoorwayHalfWidth}, false,
             kSkipBottom | kSkipTop | kSkipSouth);
    wall.box({-kHalfWall, 0.0f, kDoorwayHalfWidth}, {kHalfWall, kHeight, kHalfDepth}, false,
             kSkipBottom | kSkipTop | kSkipNorth);
    wall.box({-kHalfWall, kDoorwayHeight, -kDoorwayHalfWidth}, {kHalfWall, kHeight, kDoorwayHalfWidth}, false,
             kSkipTop | kSkipSouth | kSkipNorth);
    return wall.finish();
}

} // namespace lumina::scene::two_room
