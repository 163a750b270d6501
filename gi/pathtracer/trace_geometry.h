#pragma once
// The CPU half of the path tracer's scene: every triangle of every instance in world space
// (for the BVH), what each traced triangle is (instance, index position, material, flags),
// and the emissive triangles with the alias table that picks one by power. No GPU types:
// tests check it on its own, PathTracerScene uploads it.
#include "gi/bvh/bvh.h"
#include "gi/scene/scene.h"
#include "shaders/pathtracer/pathtracer_shared.h"

#include <cstdint>
#include <vector>

namespace lumina::gi {

struct TraceGeometry {
    std::vector<bvh::BuildTriangle> triangles; // world space; primId = index into refs
    std::vector<gpu::PtTriangle> refs;
    std::vector<gpu::PtEmitter> emitters;
    std::vector<gpu::PtAliasEntry> emitterAlias; // empty without emitters
    double emittedPower = 0.0;                   // sum over emitters of luminance x area x pi x sides
                                                 // (luminance: shaders/common/conventions.h)
};

// Index positions follow GpuScene's packing (gi/gpu_scene/gpu_scene.cpp): one index buffer,
// the meshes' indices one after another in scene order. Materials out of range are clamped
// as GpuScene clamps them.
TraceGeometry buildTraceGeometry(const scene::Scene& scene);

} // namespace lumina::gi
