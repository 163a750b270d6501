#pragma once
// A scene's distance fields on the GPU: the mesh SDF atlas (R16F or R32F 3D texture) and its
// volume table, the instance table and instance BVH the near-field tracer walks, and the
// global SDF (RG32F 3D: distance, nearest instance), composed on the GPU by
// shaders/sdf/global_sdf_compose.hlsl and recomposed only where instances moved
// (gi/sdf/global_sdf_bricks.h). Kernels trace all of it through
// shaders/sdf/sdf_scene_bindings.hlsli, bound by bindForTracing().
//
//   sdf::SceneSdf sdfs(device, scene);              // mesh SDFs built or loaded from the cache
//   sdfs.record(frame, camera.position);            // composes the global SDF (all of it, first)
//   sdfs.setInstanceTransform(7, moved);            // later: one instance moves
//   sdfs.record(frame, camera.position);            // recomposes only the bricks it touches (and
//                                                   // those the camera's move exposed)
//   sdfs.bindForTracing(frame.compute("my pass", "my/kernel")).write(0, out).dispatch(n);
//
// A single-grid global SDF covers the instances' boxes at construction; an instance that later
// moves outside it is clipped. Cascades follow the camera within the scene's initial box
// (gi/sdf/global_sdf_cascades.h): pass the camera to record().
#include "gi/core/frame_context.h"
#include "gi/sdf/global_sdf_bricks.h"
#include "gi/sdf/instance_bvh.h"
#include "gi/sdf/scene_sdf_data.h"
#include "rhi/rhi.h"

#include <cstdint>
#include <string>
#include <utility>

namespace lumina::sdf {

// What the last record() composed, and why.
struct GlobalComposeStats {
    bool skipped = false;
    bool full = false;
    uint32_t changedInstances = 0;
    uint32_t bricks = 0;
    uint64_t voxels = 0;                    // voxels recomposed (inside the grid)
    std::vector<uint32_t> scrolledCascades; // cascades whose window moved with the camera
    uint32_t exposedBricks = 0;             // bricks those moves exposed
    std::string reason; // "first compose", "1 instance(s) moved", "no instance moved", ...
};

class SceneSdf {
public:
    static constexpr const char* kComposePassName = "sdf: global compose";

    SceneSdf(rhi::IDevice& device, const scene::Scene& scene, const SceneSdfSettings& settings = {});
    SceneSdf(rhi::IDevice& device, SceneSdfData data);

    // Places an instance (index into the scene's instance list) anew; takes effect at the next
    // record(). Instances whose mesh has no SDF are ignored.
    void setInstanceTransform(uint32_t sceneInstance, const glm::mat4& transform);
    // setInstanceTransform for every instance of `scene` (the scene this was built from).
    void syncTransforms(const scene::Scene& scene);
    // The next record() recomposes the whole global SDF.
    void invalidateGlobalSdf();

    // Uploads the instance table and BVH if instances moved, moves the cascades' windows to the
    // camera, then composes the global SDF bricks the changes touched and the windows' moves
    // exposed (everything the first time); a frame with nothing to do records the compose pass
    // as skipped, with the reason. Without a camera, the last one given (at first the scene
    // camera) places the cascades. A single cascade never moves.
    void record(gi::FrameContext& frame, const glm::vec3& camera);
    void record(gi::FrameContext& frame) { record(frame, camera_); }

    // Binds the registers of shaders/sdf/sdf_scene_bindings.hlsli: b0 scene info, t0 atlas,
    // t1 volumes, t2 instances, t3 instance BVH nodes, t4 instance list, t5 global SDF, s0
    // linear clamp sampler.
    gi::ComputePass& bindForTracing(gi::ComputePass& pass) const;
    gi::ComputePass bindForTracing(gi::ComputePass&& pass) const {
        bindForTracing(pass);
        return std::move(pass);
    }

    const SceneSdfData& data() const { return data_; }
    const InstanceBvh& instanceBvh() const { return bvh_; }
    const GlobalComposeStats& lastCompose() const { return lastCompose_; }
    gpu::SdfSceneInfo sceneInfo() const { return data_.sceneInfo(uint32_t(bvh_.nodes.size()), windows_); }
    // Cascade c's window (lattice voxel of its corner) and grid as the last record() left them.
    const std::vector<glm::ivec3>& cascadeWindows() const { return windows_; }
    GlobalSdfSettings cascadeGrid(uint32_t cascade) const {
        return sdf::cascadeGrid(data_.cascades, cascade, windows_.at(cascade));
    }

    rhi::TextureHandle atlas() const { return atlas_; }
    rhi::TextureHandle globalSdf() const { return global_; }
    rhi::BufferHandle instanceBuffer() const { return instances_; }

private:
    void uploadTables(rhi::ICommandList& commands);

    rhi::IDevice& device_;
    SceneSdfData data_;
    InstanceBvh bvh_;
    std::vector<uint32_t> tableIndex_;             // scene instance -> table entry, or kNoVolume
    std::vector<GlobalSdfChangeTracker> trackers_; // one per cascade
    std::vector<glm::ivec3> windows_;              // per cascade, where its texels hold values
    glm::vec3 camera_{0.0f};
    bool tablesDirty_ = false;
    GlobalComposeStats lastCompose_;

    rhi::TextureHandle atlas_;
    rhi::TextureHandle global_;
    rhi::BufferHandle sceneInfo_;
    rhi::BufferHandle volumes_;
    rhi::BufferHandle instances_;
    rhi::BufferHandle nodes_;
    rhi::BufferHandle instanceList_;
    rhi::BufferHandle bricks_;
    rhi::BufferHandle brickInstances_;
    rhi::SamplerHandle linearClamp_;
};

} // namespace lumina::sdf
