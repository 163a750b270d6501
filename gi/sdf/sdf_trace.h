#pragma once
// Sphere tracing through one mesh's SDF in the atlas, on the CPU: the reference twin of
// sdfTraceVolume() in shaders/common/sdf_sampling.hlsli (same clipping, steps and stopping
// rule), for tests that compare the GPU against the CPU and the SDF against the BVH.
#include "gi/sdf/sdf_atlas.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>

namespace lumina::sdf {

struct SdfTraceSettings {
    uint32_t maxSteps = 128;
    // A hit when the sampled distance falls below this many voxels. Small values track
    // silhouettes closely; thin open surfaces (stored unsigned) need about half a voxel,
    // since trilinear filtering between voxel centres never quite reaches zero there.
    float hitThresholdVoxels = 0.1f;
};

struct SdfTraceResult {
    bool hit = false;
    float t = std::numeric_limits<float>::infinity(); // along the normalised direction
    uint32_t steps = 0;
};

// `direction` must be normalised (distances and t are in mesh units). Starting inside the
// surface is a hit at the volume entry (t = max(0, entry)).
SdfTraceResult traceSdf(const SdfAtlas& atlas, uint32_t volume, const glm::vec3& origin,
                        const glm::vec3& direction, float tMax = std::numeric_limits<float>::infinity(),
                        const SdfTraceSettings& settings = {});

} // namespace lumina::sdf
