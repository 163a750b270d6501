#include "gi/ddgi/ddgi_volumes.h"

#include <algorithm>
#include <cmath>

namespace lumina::gi {

namespace {

DdgiVolumePlacement cellCentred(const scene::Bounds& box, const glm::uvec3& counts) {
    glm::vec3 extent = box.max - box.min;
    int longest = 0;
    for (int axis = 1; axis < 3; ++axis) {
        longest = extent[axis] > extent[longest] ? axis : longest;
    }
    // An axis thinner than one cell of the longest (a flat scene) gets cells of that size.
    const float cell = extent[longest] / float(counts[longest]);
    const glm::vec3 centre = 0.5f * (box.min + box.max);
    for (int axis = 0; axis < 3; ++axis) {
        if (extent[axis] < cell) {
            extent[axis] = cell * float(counts[axis]);
        }
    }
    DdgiVolumePlacement v;
    v.counts = counts;
    v.spacing = extent / glm::vec3(counts);
    v.origin = centre - 0.5f * extent + 0.5f * v.spacing;
    return v;
}

} // namespace

std::vector<DdgiVolumePlacement> placeDdgiVolumes(const DdgiSettings& settings, const scene::Bounds& sceneBox,
                                                  const glm::vec3& camera) {
    std::vector<DdgiVolumePlacement> volumes;
    if (!settings.volumes.empty()) {
        for (const DdgiVolumeBox& box : settings.volumes) {
            volumes.push_back(cellCentred(box.box, box.counts));
        }
        // Finest first: the sampling takes the first volume that holds a point.
        std::ranges::stable_sort(volumes, {}, [](const DdgiVolumePlacement& v) {
            return std::min({v.spacing.x, v.spacing.y, v.spacing.z});
        });
        return volumes;
    }
    if (settings.cascades > 0) {
        for (uint32_t c = 0; c < settings.cascades; ++c) {
            DdgiVolumePlacement v;
            v.counts = settings.probeCounts;
            v.spacing = glm::vec3(settings.cascadeSpacing * float(1u << c));
            const glm::vec3 half = 0.5f * glm::vec3(v.counts - 1u) * v.spacing;
            v.origin = glm::floor((camera - half) / v.spacing + 0.5f) * v.spacing;
            volumes.push_back(v);
        }
        return volumes;
    }
    volumes.push_back(cellCentred(sceneBox, settings.probeCounts));
    return volumes;
}

DdgiAtlasLayout ddgiAtlasLayout(const std::vector<DdgiVolumePlacement>& volumes) {
    DdgiAtlasLayout layout;
    for (const DdgiVolumePlacement& v : volumes) {
        layout.firstProbe.push_back(layout.probes);
        layout.firstRow.push_back(layout.tileRows);
        layout.probes += v.counts.x * v.counts.y * v.counts.z;
        layout.tileRows += v.counts.z;
        layout.tilesAcross = std::max(layout.tilesAcross, v.counts.x * v.counts.y);
    }
    return layout;
}

DdgiScroll scrollDdgiVolume(const DdgiVolumePlacement& before, const DdgiVolumePlacement& after,
                            const glm::uvec3& offset) {
    if (before.counts != after.counts || before.spacing != after.spacing) {
        return {.reset = true};
    }
    const glm::ivec3 n(after.counts);
    const glm::ivec3 moved(glm::round((after.origin - before.origin) / after.spacing));
    DdgiScroll scroll;
    for (int axis = 0; axis < 3; ++axis) {
        const int d = moved[axis];
        if (std::abs(d) >= n[axis]) {
            return {.reset = true};
        }
        // Lattice point c now is c + d before: slot (c + d + offset) mod n.
        scroll.offset[axis] = uint32_t(((int(offset[axis]) + d) % n[axis] + n[axis]) % n[axis]);
        scroll.enteredMin[axis] = uint32_t(d > 0 ? n[axis] - d : 0);
        scroll.enteredMax[axis] = uint32_t(d > 0 ? n[axis] : -d);
    }
    return scroll;
}

gpu::DdgiVolumeInfo ddgiVolumeInfo(const DdgiVolumePlacement& volume, const DdgiAtlasLayout& layout,
                                   uint32_t index, float maxOffset, uint32_t flags,
                                   const DdgiScroll& scroll) {
    const glm::uvec3 c = volume.counts;
    gpu::DdgiVolumeInfo info{};
    info.origin = volume.origin;
    info.distanceUnit = std::max({volume.spacing.x, volume.spacing.y, volume.spacing.z});
    info.spacing = volume.spacing;
    info.maxOffset = maxOffset;
    info.counts = c;
    info.firstProbe = layout.firstProbe.at(index);
    info.tilesPerRow = c.x * c.y;
    info.firstTileRow = layout.firstRow.at(index);
    info.flags = flags;
    info.probeCount = c.x * c.y * c.z;
    info.scroll = scroll.offset;
    info.enteredMin = scroll.enteredMin;
    info.enteredMax = scroll.enteredMax;
    return info;
}

} // namespace lumina::gi
