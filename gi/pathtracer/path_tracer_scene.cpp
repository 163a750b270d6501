#include "gi/pathtracer/path_tracer_scene.h"

#include "gi/pathtracer/light_packing.h"

#include <algorithm>
#include <chrono>
#include <string>

namespace lumina::gi {

namespace {

// The GPU traversal keeps LUMINA_BVH_STACK_SIZE (64) entries: trees up to one level deeper.
constexpr uint32_t kMaxBvhDepth = 65;

template <typename T>
rhi::BufferHandle structuredBuffer(rhi::IDevice& device, const std::vector<T>& data, const char* name,
                                   uint64_t& bytes) {
    const T placeholder{}; // a binding needs a buffer even when the kernel reads none of it
    const T* source = data.empty() ? &placeholder : data.data();
    const uint64_t size = std::max<size_t>(data.size(), 1) * sizeof(T);
    bytes += size;
    return rhi::createBufferWithData(
        device,
        {.size = size, .structStride = sizeof(T), .usage = rhi::BufferUsage::Structured, .debugName = name},
        source, size);
}

} // namespace

PathTracerScene::PathTracerScene(rhi::IDevice& device, const scene::Scene& scene,
                                 const bvh::BvhBuildSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    geometry_ = buildTraceGeometry(scene);
    if (geometry_.triangles.empty()) {
        throw rhi::Error("path tracer: scene '" + scene.name + "' has no triangles");
    }
    bvh_ = bvh::buildBvh(geometry_.triangles, settings);
    stats_.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (bvh_.depth > kMaxBvhDepth) {
        throw rhi::Error("path tracer: the BVH of scene '" + scene.name + "' is " +
                         std::to_string(bvh_.depth) + " levels deep, more than the GPU traversal's " +
                         std::to_string(kMaxBvhDepth));
    }
    // The world triangles live on in the BVH; the build copies are no longer needed.
    geometry_.triangles.clear();
    geometry_.triangles.shrink_to_fit();

    gpuScene_ = std::make_unique<GpuScene>(device, scene);
    uint64_t bytes = 0;
    bvhNodes = structuredBuffer(device, bvh_.nodes, "path tracer: bvh nodes", bytes);
    bvhTriangles = structuredBuffer(device, bvh_.triangles, "path tracer: bvh triangles", bytes);
    triangles = structuredBuffer(device, geometry_.refs, "path tracer: triangles", bytes);
    emitters = structuredBuffer(device, geometry_.emitters, "path tracer: emitters", bytes);
    emitterAlias =
        structuredBuffer(device, geometry_.emitterAlias, "path tracer: emitter alias table", bytes);
    lights = structuredBuffer(device, packLights(scene.lights), "path tracer: lights", bytes);

    stats_.triangles = geometry_.refs.size();
    stats_.emitters = uint32_t(geometry_.emitters.size());
    stats_.lights = uint32_t(scene.lights.size());
    stats_.bvhNodes = uint32_t(bvh_.nodes.size());
    stats_.bvhDepth = bvh_.depth;
    stats_.gpuBytes = bytes;
}

} // namespace lumina::gi
