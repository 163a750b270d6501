#include "gi/sdf/sdf_trace.h"

#include "shaders/common/ray_box.hlsli"

#include <algorithm>

namespace lumina::sdf {

SdfTraceResult traceSdf(const SdfAtlas& atlas, uint32_t volume, const glm::vec3& origin,
                        const glm::vec3& direction, float tMax, const SdfTraceSettings& settings) {
    SdfTraceResult result;
    const gpu::SdfVolumeDesc& desc = atlas.volumes.at(volume);
    const glm::vec3 boxMin(desc.volumeMinAndVoxelSize), boxMax(desc.volumeMaxAndInvVoxelSize);
    // Clip the ray to the volume box (no widening: a ray lost to rounding only grazes padding).
    const glm::vec2 range = gpu::boxEntryExit(origin, gpu::safeReciprocal3(direction), boxMin, boxMax);
    float t = std::max(range.x, 0.0f);
    const float tExit = std::min(range.y, tMax);
    if (!(t <= tExit)) {
        return result;
    }
    const float voxelSize = desc.volumeMinAndVoxelSize.w;
    const float threshold = settings.hitThresholdVoxels * voxelSize;
    for (uint32_t step = 0; step < settings.maxSteps; ++step) {
        result.steps = step + 1;
        const float d = sampleSdf(atlas, volume, origin + t * direction);
        if (d < threshold) {
            result.hit = true;
            result.t = t;
            return result;
        }
        t += d;
        if (t > tExit) {
            return result;
        }
    }
    return result; // out of steps: a miss
}

} // namespace lumina::sdf
