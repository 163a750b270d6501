#include "gi/sdf/global_sdf_bricks.h"

#include "gi/sdf/scene_sdf_data.h"
#include "gi/sdf/sdf_cache.h"

#include <algorithm>
#include <cmath>

namespace lumina::sdf {

glm::uvec3 brickDims(const GlobalSdfSettings& grid) {
    return (grid.dims + (kSdfBrickSize - 1)) / kSdfBrickSize;
}

float influenceMargin(const GlobalSdfSettings& grid, const gpu::SdfInstanceDesc& instance) {
    const float shell = instance.worldMax.w > 0.0f ? instance.worldMax.w + grid.openShellExtra : 0.0f;
    return grid.maxDistance + shell + grid.voxelSize;
}

BrickRange bricksTouched(const GlobalSdfSettings& grid, const bvh::Aabb& box, float margin) {
    BrickRange range;
    if (box.empty()) {
        return range;
    }
    const glm::vec3 lo = (box.min - margin - grid.boundsMin) / grid.voxelSize;
    const glm::vec3 hi = (box.max + margin - grid.boundsMin) / grid.voxelSize;
    const glm::vec3 dims(grid.dims);
    for (int a = 0; a < 3; ++a) {
        // Voxels whose cell [i, i + 1) meets [lo, hi]: a superset of the voxel centres inside.
        if (!(hi[a] >= 0.0f && lo[a] < dims[a])) {
            return range;
        }
        const uint32_t first = uint32_t(std::max(lo[a], 0.0f));
        const uint32_t last = std::min(uint32_t(hi[a]), grid.dims[a] - 1);
        range.lo[a] = first / kSdfBrickSize;
        range.hi[a] = last / kSdfBrickSize;
    }
    range.empty = false;
    return range;
}

ComposeBatch makeComposeBatch(const GlobalSdfSettings& grid, std::span<const gpu::SdfInstanceDesc> instances,
                              const std::vector<uint8_t>& dirty) {
    const glm::uvec3 bricks = brickDims(grid);
    auto brickIndex = [&](uint32_t x, uint32_t y, uint32_t z) {
        return (size_t(z) * bricks.y + y) * bricks.x + x;
    };
    // Dense slot per dirty brick, so the lists fill in one pass over the instances (which
    // keeps every list ascending).
    std::vector<uint32_t> slot(dirty.size(), UINT32_MAX);
    ComposeBatch batch;
    for (uint32_t z = 0; z < bricks.z; ++z) {
        for (uint32_t y = 0; y < bricks.y; ++y) {
            for (uint32_t x = 0; x < bricks.x; ++x) {
                const size_t i = brickIndex(x, y, z);
                if (i < dirty.size() && dirty[i] != 0) {
                    slot[i] = uint32_t(batch.bricks.size());
                    gpu::GlobalSdfBrick brick{};
                    brick.coordAndInstances = glm::uvec4(x | (y << 10) | (z << 20), 0u, 0u, 0u);
                    batch.bricks.push_back(brick);
                    const glm::uvec3 first = glm::uvec3(x, y, z) * kSdfBrickSize;
                    const glm::uvec3 count = glm::min(grid.dims - first, glm::uvec3(kSdfBrickSize));
                    batch.voxels += uint64_t(count.x) * count.y * count.z;
                }
            }
        }
    }
    std::vector<std::vector<uint32_t>> lists(batch.bricks.size());
    for (uint32_t i = 0; i < instances.size(); ++i) {
        const BrickRange range =
            bricksTouched(grid, worldBox(instances[i]), influenceMargin(grid, instances[i]));
        if (range.empty) {
            continue;
        }
        for (uint32_t z = range.lo.z; z <= range.hi.z; ++z) {
            for (uint32_t y = range.lo.y; y <= range.hi.y; ++y) {
                for (uint32_t x = range.lo.x; x <= range.hi.x; ++x) {
                    const uint32_t s = slot[brickIndex(x, y, z)];
                    if (s != UINT32_MAX) {
                        lists[s].push_back(i);
                    }
                }
            }
        }
    }
    for (size_t b = 0; b < lists.size(); ++b) {
        batch.bricks[b].coordAndInstances.y = uint32_t(batch.brickInstances.size());
        batch.bricks[b].coordAndInstances.z = uint32_t(lists[b].size());
        batch.brickInstances.insert(batch.brickInstances.end(), lists[b].begin(), lists[b].end());
    }
    return batch;
}

uint64_t instanceHash(const gpu::SdfInstanceDesc& instance) {
    uint64_t hash = fnv1a64(instance.objectToWorld, sizeof(instance.objectToWorld));
    return fnv1a64(&instance.ids.x, sizeof(instance.ids.x), hash);
}

GlobalSdfChangeTracker::Changes
GlobalSdfChangeTracker::update(std::span<const gpu::SdfInstanceDesc> instances) {
    const glm::uvec3 bricks = brickDims(grid_);
    Changes changes;
    changes.dirtyBricks.assign(size_t(bricks.x) * bricks.y * bricks.z, 0);
    const bool full = hashes_.size() != instances.size() || hashes_.empty();
    auto mark = [&](const bvh::Aabb& box, float margin) {
        const BrickRange range = bricksTouched(grid_, box, margin);
        if (range.empty) {
            return;
        }
        for (uint32_t z = range.lo.z; z <= range.hi.z; ++z) {
            for (uint32_t y = range.lo.y; y <= range.hi.y; ++y) {
                for (uint32_t x = range.lo.x; x <= range.hi.x; ++x) {
                    changes.dirtyBricks[(size_t(z) * bricks.y + y) * bricks.x + x] = 1;
                }
            }
        }
    };
    if (full) {
        std::fill(changes.dirtyBricks.begin(), changes.dirtyBricks.end(), uint8_t(1));
        changes.full = true;
        changes.changedInstances = uint32_t(instances.size());
        changes.reason = hashes_.empty() ? "first compose" : "instance count changed";
        hashes_.resize(instances.size());
        boxes_.resize(instances.size());
        margins_.resize(instances.size());
        for (size_t i = 0; i < instances.size(); ++i) {
            hashes_[i] = instanceHash(instances[i]);
            boxes_[i] = worldBox(instances[i]);
            margins_[i] = influenceMargin(grid_, instances[i]);
        }
    } else {
        for (size_t i = 0; i < instances.size(); ++i) {
            const uint64_t hash = instanceHash(instances[i]);
            if (hash == hashes_[i]) {
                continue;
            }
            ++changes.changedInstances;
            const bvh::Aabb box = worldBox(instances[i]);
            mark(boxes_[i], margins_[i]);
            const float margin = influenceMargin(grid_, instances[i]);
            mark(box, margin);
            hashes_[i] = hash;
            boxes_[i] = box;
            margins_[i] = margin;
        }
        changes.reason = changes.changedInstances == 0
                             ? "no instance moved"
                             : std::to_string(changes.changedInstances) + " instance(s) moved";
    }
    changes.dirtyBrickCount =
        uint32_t(std::count(changes.dirtyBricks.begin(), changes.dirtyBricks.end(), uint8_t(1)));
    if (!full && changes.changedInstances != 0 && changes.dirtyBrickCount == 0) {
        changes.reason += ", all outside the grid";
    }
    return changes;
}

} // namespace lumina::sdf
