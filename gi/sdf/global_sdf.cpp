#include "gi/sdf/global_sdf.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace lumina::sdf {
namespace {

struct PreparedInstance {
    glm::mat4 worldToMesh;
    float scale;
    glm::vec3 worldMin, worldMax; // world box of the instance's volume
    uint32_t volume;
    float shell;     // subtracted from open volumes' distances
    bool closed;     // a signed solid: may get a thin-solid shell instead
    float cullShell; // the most that is subtracted: the open shell, or a thin solid's largest
};

float boxDistance(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
    return glm::length(glm::max(glm::max(lo - p, glm::vec3(0.0f)), p - hi));
}

// Gradient of a volume's field at p, from tetrahedral differences e apart (four samples).
glm::vec3 gradientAt(const SdfAtlas& atlas, uint32_t volume, const glm::vec3& p, float e) {
    const glm::vec3 corners[4] = {
        {1.0f, -1.0f, -1.0f}, {-1.0f, -1.0f, 1.0f}, {-1.0f, 1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}};
    glm::vec3 sum(0.0f);
    for (const glm::vec3& corner : corners) {
        sum += corner * sampleSdf(atlas, volume, p + e * corner);
    }
    return sum / (4.0f * e);
}

// Its direction; zero where the differences vanish (the middle of a thin slab).
glm::vec3 unitGradient(const SdfAtlas& atlas, uint32_t volume, const glm::vec3& p, float e) {
    const glm::vec3 gradient = gradientAt(atlas, volume, p, e);
    return gradient / std::max(glm::length(gradient), 1e-30f);
}

} // namespace

bvh::Aabb instanceWorldBox(const gpu::SdfVolumeDesc& volume, const glm::mat4& meshToWorld) {
    bvh::Aabb box;
    const glm::vec3 lo(volume.volumeMinAndVoxelSize), hi(volume.volumeMaxAndInvVoxelSize);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
        box.extend(glm::vec3(meshToWorld * glm::vec4(corner, 1.0f)));
    }
    return box;
}

float instanceDistanceScale(const glm::mat4& meshToWorld) {
    return std::min({glm::length(glm::vec3(meshToWorld[0])), glm::length(glm::vec3(meshToWorld[1])),
                     glm::length(glm::vec3(meshToWorld[2]))});
}

float openSurfaceShell(const gpu::SdfVolumeDesc& volume, float distanceScale, float globalVoxelSize) {
    if ((volume.dims.w & LUMINA_SDF_VOLUME_OPEN) == 0) {
        return 0.0f;
    }
    return LUMINA_SDF_OPEN_SURFACE_GLOBAL_SHELL_VOXELS * globalVoxelSize +
           LUMINA_SDF_OPEN_SURFACE_THRESHOLD_VOXELS * volume.volumeMinAndVoxelSize.w * distanceScale;
}

float thinSolidShell(const SdfAtlas& atlas, uint32_t volume, const glm::vec3& p, float distance,
                     float halfThickness) {
    if (distance <= -halfThickness) {
        return 0.0f; // deep enough where the voxel centre itself lies
    }
    const gpu::SdfVolumeDesc& desc = atlas.volumes.at(volume);
    const float voxel = desc.volumeMinAndVoxelSize.w;
    const float e = 0.5f * voxel;
    // The nearest surface point, from p held a voxel inside the volume's box (beyond it the
    // sample is only a lower bound, and within half a voxel of its faces the clamped samples
    // flatten the gradient; the surface lies two voxels inside): along the gradient by the
    // distance there, and once more by what is left.
    glm::vec3 x = glm::clamp(p, glm::vec3(desc.volumeMinAndVoxelSize) + voxel,
                             glm::vec3(desc.volumeMaxAndInvVoxelSize) - voxel);
    // A distance changes by at most what one moves: a steeper field is the sign flip a solid's
    // missing face leaves in its SDF (a block without its bottom, a wall without the faces it
    // shares with the floor), not a thin part, and keeps its distance.
    const glm::vec3 gradient = gradientAt(atlas, volume, x, e);
    const float slope = glm::length(gradient);
    if (slope > LUMINA_SDF_THIN_SOLID_MAX_SLOPE) {
        return 0.0f;
    }
    const glm::vec3 n = gradient / std::max(slope, 1e-30f);
    x -= n * sampleSdf(atlas, volume, x);
    x -= n * sampleSdf(atlas, volume, x);
    // Most voxels lie beside a face of a thick solid: one sample straight in proves it.
    if (sampleSdf(atlas, volume, x - n * (1.5f * halfThickness)) <= -halfThickness) {
        return 0.0f;
    }
    // Else down the gradient, a quarter of the half thickness a step: the depth grows by a step
    // each time until the middle of the solid (a straight line from a point near an edge would
    // run under the other face and stay shallow). Stop once deep enough, or once a step inside
    // gets no deeper (past the middle of a thin part) or leaves the solid. The surface point
    // counts as depth 0, so a solid thinner than a step, which every sample misses, gets the
    // whole shell.
    const float step = 0.25f * halfThickness;
    float deepest = std::min(distance, 0.0f);
    float last = 0.0f;
    for (uint32_t i = 0; i < LUMINA_SDF_THIN_SOLID_STEPS; ++i) {
        x -= unitGradient(atlas, volume, x, e) * step;
        const float s = sampleSdf(atlas, volume, x);
        if (s >= last && last < 0.0f) {
            break;
        }
        last = s;
        deepest = std::min(deepest, s);
        if (deepest <= -halfThickness) {
            break;
        }
    }
    return std::max(halfThickness + deepest, 0.0f);
}

GlobalSdf composeGlobalSdf(const SdfAtlas& atlas, std::span<const SdfInstance> instances,
                           const GlobalSdfSettings& settings) {
    if (!(settings.voxelSize > 0.0f) || settings.dims.x == 0 || settings.dims.y == 0 ||
        settings.dims.z == 0) {
        throw std::invalid_argument("composeGlobalSdf: empty grid or non-positive voxel size");
    }
    const float thinHalfThickness = LUMINA_SDF_THIN_SOLID_HALF_THICKNESS_VOXELS * settings.voxelSize;
    std::vector<PreparedInstance> prepared;
    for (size_t i = 0; i < instances.size(); ++i) {
        const SdfInstance& inst = instances[i];
        if (inst.volume >= atlas.volumes.size()) {
            throw std::invalid_argument("composeGlobalSdf: instance " + std::to_string(i) + " names volume " +
                                        std::to_string(inst.volume) + " of " +
                                        std::to_string(atlas.volumes.size()));
        }
        PreparedInstance p;
        p.worldToMesh = glm::inverse(inst.meshToWorld);
        p.scale = instanceDistanceScale(inst.meshToWorld);
        p.volume = inst.volume;
        const bvh::Aabb box = instanceWorldBox(atlas.volumes[inst.volume], inst.meshToWorld);
        p.worldMin = box.min;
        p.worldMax = box.max;
        p.shell = openSurfaceShell(atlas.volumes[inst.volume], p.scale, settings.voxelSize);
        p.closed = (atlas.volumes[inst.volume].dims.w & LUMINA_SDF_VOLUME_OPEN) == 0;
        p.cullShell = p.closed ? thinHalfThickness : p.shell;
        prepared.push_back(p);
    }

    GlobalSdf grid;
    grid.dims = settings.dims;
    grid.boundsMin = settings.boundsMin;
    grid.voxelSize = settings.voxelSize;
    const size_t voxels = size_t(grid.dims.x) * grid.dims.y * grid.dims.z;
    grid.distances.assign(voxels, settings.maxDistance);
    grid.instances.assign(voxels, kNoInstance);

    std::atomic<uint32_t> nextSlice{0};
    auto worker = [&] {
        for (uint32_t z = nextSlice++; z < grid.dims.z; z = nextSlice++) {
            for (uint32_t y = 0; y < grid.dims.y; ++y) {
                for (uint32_t x = 0; x < grid.dims.x; ++x) {
                    const glm::vec3 p = grid.voxelCentre(x, y, z);
                    float best = settings.maxDistance;
                    uint32_t bestInstance = kNoInstance;
                    for (uint32_t i = 0; i < prepared.size(); ++i) {
                        const PreparedInstance& inst = prepared[i];
                        // Everything of the instance lies in its world box: it cannot be nearer.
                        const float toBox = boxDistance(p, inst.worldMin, inst.worldMax);
                        if (toBox - inst.cullShell >= best) {
                            continue;
                        }
                        const glm::vec3 local(inst.worldToMesh * glm::vec4(p, 1.0f));
                        const float sampled = sampleSdf(atlas, inst.volume, local);
                        float d = sampled * inst.scale - inst.shell;
                        const float weight = inst.closed ? gpu::sdfThinSolidShellWeight(d, settings.voxelSize,
                                                                                        settings.maxDistance)
                                                         : 0.0f;
                        float thin = 0.0f;
                        if (weight > 0.0f && d - thinHalfThickness < best) {
                            thin = weight * inst.scale *
                                   thinSolidShell(atlas, inst.volume, local, sampled,
                                                  thinHalfThickness / inst.scale);
                        }
                        // Without a thin shell the box test holds as before (a sample can round
                        // below it).
                        if (thin == 0.0f && toBox - inst.shell >= best) {
                            continue;
                        }
                        d -= thin;
                        if (d < best) {
                            best = d;
                            bestInstance = i;
                        }
                    }
                    const size_t index = grid.voxelIndex(x, y, z);
                    grid.distances[index] = std::max(best, -settings.maxDistance);
                    grid.instances[index] = bestInstance;
                }
            }
        }
    };
    const uint32_t threadCount =
        std::min(grid.dims.z, settings.threads != 0 ? settings.threads
                                                    : std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> threads;
    for (uint32_t i = 1; i < threadCount; ++i) {
        threads.emplace_back(worker);
    }
    worker();
    for (std::thread& t : threads) {
        t.join();
    }
    return grid;
}

} // namespace lumina::sdf
