#pragma once
// Where a DDGI technique's probes are (docs/ddgi.md): one volume fitted to the scene, the volumes
// a scene file or the CLI gives, or camera-centred cascades; and how their probes share one
// probe buffer and one pair of atlases (ddgi_shared.h).
//
//   auto volumes = placeDdgiVolumes(settings, scene.worldBounds(), camera.position);
//   DdgiAtlasLayout layout = ddgiAtlasLayout(volumes);
#include "gi/ddgi/ddgi_settings.h"
#include "gi/scene/scene.h"
#include "shaders/ddgi/ddgi_shared.h"

#include <glm/glm.hpp>
#include <vector>

namespace lumina::gi {

struct DdgiVolumePlacement {
    glm::vec3 origin{0.0f};  // world position of lattice point (0, 0, 0)
    glm::vec3 spacing{1.0f}; // between lattice points
    glm::uvec3 counts{2};
    bool operator==(const DdgiVolumePlacement&) const = default;
};

// The volumes `settings` asks for, finest first. A fitted or given box gets its probes at the
// centres of counts cells dividing it (no probe on the box's faces, where a room's walls are); an
// axis thinner than a cell of the longest (a flat scene) gets cells of that size. Cascade c is counts probes
// cascadeSpacing x 2^c apart, centred on `camera` and snapped to whole cells of its own, so a
// moving camera moves it by whole cells.
std::vector<DdgiVolumePlacement> placeDdgiVolumes(const DdgiSettings& settings, const scene::Bounds& sceneBox,
                                                  const glm::vec3& camera);

struct DdgiAtlasLayout {
    std::vector<uint32_t> firstProbe; // per volume: global index of its probe 0
    std::vector<uint32_t> firstRow;   // per volume: first tile row in the atlases
    uint32_t probes = 0;
    uint32_t tilesAcross = 0; // widest volume's counts.x * counts.y
    uint32_t tileRows = 0;    // summed counts.z
};

DdgiAtlasLayout ddgiAtlasLayout(const std::vector<DdgiVolumePlacement>& volumes);

// How a volume's probe slots follow a move (ddgi_shared.h, DdgiVolumeInfo::scroll): the slot
// offset after it, the lattice planes that entered with it, or a reset when the volume changed
// shape or moved by its own size or more along an axis (nothing of it stays).
struct DdgiScroll {
    glm::uvec3 offset{0};
    glm::uvec3 enteredMin{0}, enteredMax{0}; // per axis; equal: no plane entered on that axis
    bool reset = false;
};
DdgiScroll scrollDdgiVolume(const DdgiVolumePlacement& before, const DdgiVolumePlacement& after,
                            const glm::uvec3& offset);

// The shader's view of a volume.
gpu::DdgiVolumeInfo ddgiVolumeInfo(const DdgiVolumePlacement& volume, const DdgiAtlasLayout& layout,
                                   uint32_t index, float maxOffset, uint32_t flags, const DdgiScroll& scroll);

} // namespace lumina::gi
