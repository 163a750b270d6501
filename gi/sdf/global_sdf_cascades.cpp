#include "gi/sdf/global_sdf_cascades.h"

#include "gi/sdf/global_sdf_bricks.h"
#include "gi/sdf/scene_sdf_data.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lumina::sdf {
namespace {

// x mod m in [0, m) for any sign of x.
int32_t positiveMod(int32_t x, int32_t m) {
    const int32_t r = x % m;
    return r < 0 ? r + m : r;
}

} // namespace

GlobalSdfCascadeLayout cascadeLayoutFor(const bvh::Aabb& sceneBox, uint32_t resolution, uint32_t padding,
                                        float maxDistanceVoxels, uint32_t maxCascades,
                                        float finestVoxelSize) {
    if (maxCascades < 1 || maxCascades > LUMINA_SDF_MAX_CASCADES) {
        throw std::invalid_argument("global SDF cascades: " + std::to_string(maxCascades) + " outside [1, " +
                                    std::to_string(LUMINA_SDF_MAX_CASCADES) + "]");
    }
    if (!(finestVoxelSize > 0.0f) || !std::isfinite(finestVoxelSize)) {
        throw std::invalid_argument("global SDF finest voxel size must be positive and finite, got " +
                                    std::to_string(finestVoxelSize));
    }
    const GlobalSdfSettings fitted = globalGridFor(sceneBox, resolution, padding, maxDistanceVoxels);
    GlobalSdfCascadeLayout layout;
    layout.maxDistanceVoxels = maxDistanceVoxels;
    layout.coverBox = {fitted.boundsMin, fitted.boundsMin + glm::vec3(fitted.dims) * fitted.voxelSize};
    if (maxCascades == 1 || fitted.voxelSize <= finestVoxelSize) {
        // The scene-fitted grid itself: a lattice starting at its corner, a window that never moves.
        layout.count = 1;
        layout.dims = fitted.dims;
        layout.finestVoxelSize = fitted.voxelSize;
        layout.latticeOrigin = fitted.boundsMin;
        return layout;
    }
    // Halve from the fitted voxel size (the coarsest cascade covers the scene) down to the finest
    // wanted; halving is exact in floating point, so cascade c's voxel is exactly finest * 2^c.
    layout.count = 1;
    float voxel = fitted.voxelSize;
    while (voxel > finestVoxelSize && layout.count < maxCascades) {
        voxel *= 0.5f;
        ++layout.count;
    }
    layout.finestVoxelSize = voxel;
    const uint32_t side = (resolution + kSdfBrickSize - 1) / kSdfBrickSize * kSdfBrickSize;
    layout.dims = glm::uvec3(side);
    layout.latticeOrigin = layout.coverBox.centre();
    return layout;
}

glm::ivec3 cascadeWindowFor(const GlobalSdfCascadeLayout& layout, uint32_t cascade, const glm::vec3& camera) {
    if (!layout.scrolls()) {
        return glm::ivec3(0);
    }
    const float voxel = layout.voxelSize(cascade);
    glm::ivec3 window;
    for (int a = 0; a < 3; ++a) {
        const float side = float(layout.dims[a]);
        const float lo = (layout.coverBox.min[a] - layout.latticeOrigin[a]) / voxel;
        const float hi = (layout.coverBox.max[a] - layout.latticeOrigin[a]) / voxel;
        float corner = (camera[a] - layout.latticeOrigin[a]) / voxel - 0.5f * side;
        corner = hi - lo <= side ? 0.5f * (lo + hi - side) : std::clamp(corner, lo, hi - side);
        // A camera far outside (or not finite) must not overflow the lattice index.
        corner = std::isfinite(corner) ? std::clamp(corner, -1e8f, 1e8f) : 0.0f;
        window[a] = int32_t(std::lround(corner / float(kSdfBrickSize))) * int32_t(kSdfBrickSize);
    }
    return window;
}

GlobalSdfSettings cascadeGrid(const GlobalSdfCascadeLayout& layout, uint32_t cascade,
                              const glm::ivec3& window) {
    GlobalSdfSettings grid;
    grid.voxelSize = layout.voxelSize(cascade);
    grid.boundsMin = layout.latticeOrigin + glm::vec3(window) * grid.voxelSize;
    grid.dims = layout.dims;
    grid.maxDistance = layout.maxDistanceVoxels * grid.voxelSize;
    grid.openShellExtra =
        LUMINA_SDF_OPEN_SURFACE_GLOBAL_SHELL_VOXELS * (grid.voxelSize - layout.finestVoxelSize);
    return grid;
}

std::vector<uint8_t> exposedBricks(const GlobalSdfCascadeLayout& layout, const glm::ivec3& from,
                                   const glm::ivec3& to, uint32_t* count) {
    const GlobalSdfSettings grid = cascadeGrid(layout, 0, to);
    const glm::uvec3 bricks = brickDims(grid);
    std::vector<uint8_t> dirty(size_t(bricks.x) * bricks.y * bricks.z, 0);
    uint32_t exposed = 0;
    const glm::ivec3 dims(layout.dims);
    for (uint32_t z = 0; z < bricks.z; ++z) {
        for (uint32_t y = 0; y < bricks.y; ++y) {
            for (uint32_t x = 0; x < bricks.x; ++x) {
                // Lattice voxels of the brick: [first, first + brick size), clipped to the window.
                const glm::ivec3 first = to + glm::ivec3(x, y, z) * int32_t(kSdfBrickSize);
                const glm::ivec3 last = glm::min(first + int32_t(kSdfBrickSize), to + dims) - 1;
                const bool held = glm::all(glm::greaterThanEqual(first, from)) &&
                                  glm::all(glm::lessThan(last, from + dims));
                if (!held) {
                    dirty[(size_t(z) * bricks.y + y) * bricks.x + x] = 1;
                    ++exposed;
                }
            }
        }
    }
    if (count != nullptr) {
        *count = exposed;
    }
    return dirty;
}

glm::uvec3 cascadeTexel(const GlobalSdfCascadeLayout& layout, const glm::ivec3& window,
                        const glm::uvec3& voxel) {
    glm::uvec3 texel;
    for (int a = 0; a < 3; ++a) {
        texel[a] = uint32_t(positiveMod(window[a] + int32_t(voxel[a]), int32_t(layout.dims[a])));
    }
    return texel;
}

uint64_t cascadeBytes(const GlobalSdfCascadeLayout& layout) {
    return uint64_t(layout.dims.x) * layout.dims.y * layout.dims.z * layout.count * 2 * sizeof(float);
}

std::string describeCascades(const GlobalSdfCascadeLayout& layout) {
    std::string out = std::to_string(layout.dims.x) + "x" + std::to_string(layout.dims.y) + "x" +
                      std::to_string(layout.dims.z) + " voxels of ";
    for (uint32_t c = 0; c < layout.count; ++c) {
        char size[32];
        std::snprintf(size, sizeof(size), "%s%.4g", c == 0 ? "" : ", ", layout.voxelSize(c));
        out += size;
    }
    return out;
}

} // namespace lumina::sdf
