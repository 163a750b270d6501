#pragma once
// The scene as the path tracer reads it on the GPU: GpuScene (vertices, indices, instances,
// materials, textures) plus a BVH over every instance's triangles in world space (binned
// SAH on the CPU, gi/bvh/), the per-triangle references, the emissive triangles with their
// alias table, and the punctual lights.
#include "gi/bvh/bvh.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/pathtracer/trace_geometry.h"
#include "gi/scene/scene.h"
#include "rhi/rhi.h"

#include <cstdint>
#include <memory>

namespace lumina::gi {

struct PathTracerSceneStats {
    uint64_t triangles = 0;
    uint32_t emitters = 0;
    uint32_t lights = 0;
    uint32_t bvhNodes = 0;
    uint32_t bvhDepth = 0;
    double buildSeconds = 0.0; // CPU: world triangles, BVH and emitter table
    uint64_t gpuBytes = 0;     // the buffers below (GpuScene's excluded)
};

// The BVH and the triangle references stay on the CPU too (tests and CPU queries use them).
class PathTracerScene {
public:
    // Throws rhi::Error when the scene has no triangles or the BVH is deeper than the GPU
    // traversal's stack.
    PathTracerScene(rhi::IDevice& device, const scene::Scene& scene,
                    const bvh::BvhBuildSettings& settings = {});

    const GpuScene& gpuScene() const { return *gpuScene_; }
    const bvh::Bvh& bvh() const { return bvh_; }
    const TraceGeometry& geometry() const { return geometry_; }
    const PathTracerSceneStats& stats() const { return stats_; }

    rhi::BufferHandle bvhNodes;     // BvhNode[]
    rhi::BufferHandle bvhTriangles; // BvhTriangle[], primId = PtTriangle index
    rhi::BufferHandle triangles;    // PtTriangle[]
    rhi::BufferHandle emitters;     // PtEmitter[] (one unused entry when there are none)
    rhi::BufferHandle emitterAlias; // PtAliasEntry[] (likewise)
    rhi::BufferHandle lights;       // GpuLight[] (likewise)

private:
    std::unique_ptr<GpuScene> gpuScene_;
    TraceGeometry geometry_;
    bvh::Bvh bvh_;
    PathTracerSceneStats stats_;
};

} // namespace lumina::gi
