#include "gi/sdf/scene_sdf.h"

#include <algorithm>
#include <stdexcept>

namespace lumina::sdf {
namespace {

// Compose groups per dispatch row: brick = groupId.y * kComposeGroupsPerRow + groupId.x,
// well inside every API's 65535 groups per dimension.
constexpr uint32_t kComposeGroupsPerRow = 1024;

template <typename T>
rhi::BufferHandle structuredBuffer(rhi::IDevice& device, const std::vector<T>& data, const char* name) {
    // Never empty: a zero-sized buffer cannot be bound; one zeroed element stands in.
    const std::vector<T> one(1, T{});
    const std::vector<T>& contents = data.empty() ? one : data;
    return rhi::createBufferWithData(device,
                                     {.size = contents.size() * sizeof(T),
                                      .structStride = sizeof(T),
                                      .usage = rhi::BufferUsage::Structured,
                                      .debugName = name},
                                     contents.data(), contents.size() * sizeof(T));
}

std::vector<bvh::Aabb> worldBoxes(const std::vector<gpu::SdfInstanceDesc>& instances) {
    std::vector<bvh::Aabb> boxes;
    boxes.reserve(instances.size());
    for (const gpu::SdfInstanceDesc& instance : instances) {
        boxes.push_back(worldBox(instance));
    }
    return boxes;
}

// A structured buffer of at least `count` elements, grown (by half again) when too small.
template <typename T>
void ensureCapacity(rhi::IDevice& device, rhi::BufferHandle& buffer, size_t count, const char* name) {
    const uint64_t needed = std::max<size_t>(count, 1) * sizeof(T);
    if (buffer && buffer->desc().size >= needed) {
        return;
    }
    buffer = device.createBuffer({.size = needed + needed / 2,
                                  .structStride = sizeof(T),
                                  .usage = rhi::BufferUsage::Structured,
                                  .debugName = name});
}

} // namespace

SceneSdf::SceneSdf(rhi::IDevice& device, const scene::Scene& scene, const SceneSdfSettings& settings)
    : SceneSdf(device, buildSceneSdfData(scene, settings)) {}

SceneSdf::SceneSdf(rhi::IDevice& device, SceneSdfData data) : device_(device), data_(std::move(data)) {
    // The cascades start where buildSceneSdfData placed the finest one: around the scene camera.
    const GlobalSdfCascadeLayout& layout = data_.cascades;
    camera_ = data_.camera;
    for (uint32_t c = 0; c < layout.count; ++c) {
        windows_.push_back(cascadeWindowFor(layout, c, camera_));
        trackers_.emplace_back(sdf::cascadeGrid(layout, c, windows_.back()));
    }
    bvh_ = buildInstanceBvh(worldBoxes(data_.instances));
    for (uint32_t i = 0; i < data_.instances.size(); ++i) {
        const uint32_t sceneInstance = data_.instances[i].ids.z;
        if (tableIndex_.size() <= sceneInstance) {
            tableIndex_.resize(sceneInstance + 1, kNoVolume);
        }
        tableIndex_[sceneInstance] = i;
    }

    const SdfAtlas& atlas = data_.atlas;
    const bool half = atlas.format == SdfTexelFormat::R16F;
    const glm::uvec3 atlasDims = atlas.volumes.empty() ? glm::uvec3(1) : atlas.dims;
    atlas_ = device.createTexture({.dimension = rhi::TextureDimension::Texture3D,
                                   .format = half ? rhi::Format::R16_FLOAT : rhi::Format::R32_FLOAT,
                                   .width = atlasDims.x,
                                   .height = atlasDims.y,
                                   .depth = atlasDims.z,
                                   .debugName = "sdf atlas"});
    if (atlas.volumes.empty()) {
        const uint16_t emptyTexel = floatToHalf(kSdfEmptyTexel);
        const float emptyTexel32 = kSdfEmptyTexel;
        rhi::writeTexture(device, *atlas_, {}, half ? static_cast<const void*>(&emptyTexel) : &emptyTexel32);
    } else {
        rhi::writeTexture(device, *atlas_, {}, atlas.data());
    }
    volumes_ = structuredBuffer(device, atlas.volumes, "sdf volumes");
    instances_ = structuredBuffer(device, data_.instances, "sdf instances");
    nodes_ = structuredBuffer(device, bvh_.nodes, "sdf instance bvh");
    instanceList_ = structuredBuffer(device, bvh_.instances, "sdf instance list");
    const gpu::SdfSceneInfo info = sceneInfo();
    sceneInfo_ = rhi::createBufferWithData(
        device, {.size = sizeof(info), .usage = rhi::BufferUsage::Constant, .debugName = "sdf scene info"},
        &info, sizeof(info));
    // Every cascade's slab, one above the other along z.
    const glm::uvec3 dims = layout.dims;
    global_ = device.createTexture({.dimension = rhi::TextureDimension::Texture3D,
                                    .format = rhi::Format::RG32_FLOAT,
                                    .width = dims.x,
                                    .height = dims.y,
                                    .depth = dims.z * layout.count,
                                    .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage,
                                    .debugName = "global sdf"});
    linearClamp_ = device.createSampler({.minFilter = rhi::Filter::Linear,
                                         .magFilter = rhi::Filter::Linear,
                                         .mipFilter = rhi::Filter::Point,
                                         .debugName = "sdf linear clamp"});
}

void SceneSdf::setInstanceTransform(uint32_t sceneInstance, const glm::mat4& transform) {
    if (sceneInstance >= tableIndex_.size() || tableIndex_[sceneInstance] == kNoVolume) {
        return;
    }
    gpu::SdfInstanceDesc& desc = data_.instances[tableIndex_[sceneInstance]];
    const gpu::SdfInstanceDesc moved =
        makeInstanceDesc(data_.atlas.volumes[desc.ids.x], desc.ids.x, transform, desc.ids.y, desc.ids.z,
                         data_.global.voxelSize);
    if (instanceHash(moved) != instanceHash(desc)) {
        desc = moved;
        tablesDirty_ = true;
    }
}

void SceneSdf::syncTransforms(const scene::Scene& scene) {
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        setInstanceTransform(i, scene.instances[i].transform);
    }
}

void SceneSdf::invalidateGlobalSdf() {
    for (GlobalSdfChangeTracker& tracker : trackers_) {
        tracker.reset();
    }
}

void SceneSdf::uploadTables(rhi::ICommandList& commands) {
    bvh_ = buildInstanceBvh(worldBoxes(data_.instances));
    // Same instance count, so the median-split tree has the same node count as before.
    commands.writeBuffer(*instances_, data_.instances.data(),
                         data_.instances.size() * sizeof(gpu::SdfInstanceDesc));
    commands.writeBuffer(*nodes_, bvh_.nodes.data(), bvh_.nodes.size() * sizeof(gpu::BvhNode));
    commands.writeBuffer(*instanceList_, bvh_.instances.data(), bvh_.instances.size() * sizeof(uint32_t));
}

void SceneSdf::record(gi::FrameContext& frame, const glm::vec3& camera) {
    camera_ = camera;
    if (tablesDirty_ && !data_.instances.empty()) {
        uploadTables(frame.commands());
    }
    tablesDirty_ = false;
    const GlobalSdfCascadeLayout& layout = data_.cascades;
    lastCompose_ = {};
    ComposeBatch batch;
    bool windowsMoved = false;
    std::string scrolled;
    for (uint32_t c = 0; c < layout.count; ++c) {
        const glm::ivec3 window = cascadeWindowFor(layout, c, camera);
        const GlobalSdfSettings grid = sdf::cascadeGrid(layout, c, window);
        GlobalSdfChangeTracker& tracker = trackers_[c];
        tracker.setGrid(grid);
        GlobalSdfChangeTracker::Changes changes = tracker.update(data_.instances);
        if (!frame.mayReuse(kComposePassName)) {
            // Forced: every brick recomposed from the same instances, to the same distances.
            std::fill(changes.dirtyBricks.begin(), changes.dirtyBricks.end(), uint8_t(1));
            changes.dirtyBrickCount = uint32_t(changes.dirtyBricks.size());
        }
        if (window != windows_[c]) {
            // The bricks that were outside the old window hold another part of the lattice.
            uint32_t exposed = 0;
            const std::vector<uint8_t> fresh = exposedBricks(layout, windows_[c], window, &exposed);
            for (size_t b = 0; b < fresh.size(); ++b) {
                changes.dirtyBricks[b] |= fresh[b];
            }
            changes.dirtyBrickCount =
                uint32_t(std::count(changes.dirtyBricks.begin(), changes.dirtyBricks.end(), 1));
            lastCompose_.scrolledCascades.push_back(c);
            lastCompose_.exposedBricks += exposed;
            scrolled += (scrolled.empty() ? "" : ", ") + std::to_string(c) + " (" + std::to_string(exposed) +
                        " bricks exposed)";
            windows_[c] = window;
            windowsMoved = true;
        }
        if (c == 0) {
            lastCompose_.full = changes.full;
            lastCompose_.changedInstances = changes.changedInstances;
            lastCompose_.reason = changes.reason;
        }
        if (changes.dirtyBrickCount == 0) {
            continue;
        }
        // This cascade's bricks join the dispatch, their lists after the previous cascades'.
        ComposeBatch part = makeComposeBatch(grid, data_.instances, changes.dirtyBricks);
        const uint32_t listOffset = uint32_t(batch.brickInstances.size());
        for (gpu::GlobalSdfBrick& brick : part.bricks) {
            brick.coordAndInstances.y += listOffset;
            brick.coordAndInstances.w = c;
        }
        batch.bricks.insert(batch.bricks.end(), part.bricks.begin(), part.bricks.end());
        batch.brickInstances.insert(batch.brickInstances.end(), part.brickInstances.begin(),
                                    part.brickInstances.end());
        batch.voxels += part.voxels;
    }
    if (!scrolled.empty()) {
        lastCompose_.reason += "; cascade(s) scrolled: " + scrolled;
    } else if (layout.scrolls()) {
        lastCompose_.reason += ", no cascade scrolled";
    }
    rhi::ICommandList& commands = frame.commands();
    if (windowsMoved) {
        const gpu::SdfSceneInfo info = sceneInfo();
        commands.writeBuffer(*sceneInfo_, &info, sizeof(info));
    }
    if (batch.bricks.empty()) {
        lastCompose_.skipped = true;
        frame.skipReused(kComposePassName, lastCompose_.reason);
        return;
    }
    lastCompose_.bricks = uint32_t(batch.bricks.size());
    lastCompose_.voxels = batch.voxels;
    if (batch.brickInstances.empty()) {
        batch.brickInstances.push_back(0); // bound, never read: every brick's list is empty
    }
    ensureCapacity<gpu::GlobalSdfBrick>(device_, bricks_, batch.bricks.size(), "sdf compose bricks");
    ensureCapacity<uint32_t>(device_, brickInstances_, batch.brickInstances.size(),
                             "sdf compose brick instances");
    commands.writeBuffer(*bricks_, batch.bricks.data(), batch.bricks.size() * sizeof(gpu::GlobalSdfBrick));
    commands.writeBuffer(*brickInstances_, batch.brickInstances.data(),
                         batch.brickInstances.size() * sizeof(uint32_t));
    const uint32_t count = uint32_t(batch.bricks.size());
    const uint32_t groupsX = std::min(count, kComposeGroupsPerRow);
    const uint32_t groupsY = (count + kComposeGroupsPerRow - 1) / kComposeGroupsPerRow;
    frame.compute(kComposePassName, "sdf/global_sdf_compose")
        .constantBuffer(0, sceneInfo_)
        .read(0, atlas_)
        .read(1, volumes_)
        .read(2, instances_)
        .read(3, bricks_)
        .read(4, brickInstances_)
        .sampler(0, linearClamp_)
        .write(0, global_)
        .constants(gpu::GlobalSdfComposeConstants{count, kComposeGroupsPerRow, 0, 0})
        .dispatch(groupsX, groupsY);
}

gi::ComputePass& SceneSdf::bindForTracing(gi::ComputePass& pass) const {
    return pass.constantBuffer(0, sceneInfo_)
        .read(0, atlas_)
        .read(1, volumes_)
        .read(2, instances_)
        .read(3, nodes_)
        .read(4, instanceList_)
        .read(5, global_)
        .sampler(0, linearClamp_);
}

} // namespace lumina::sdf
