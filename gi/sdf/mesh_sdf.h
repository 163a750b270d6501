#pragma once
// Per-mesh signed distance fields on the CPU, for the SDF ray tracing of issue 10.
//
// A mesh's SDF is a box of voxels around its bounds: `resolution` voxels along the longest
// axis (padding included), cubic voxels, the mesh centred with at least `padding` empty
// voxels on every side. Each voxel stores the signed distance at its centre:
//
// - magnitude: the exact distance to the nearest triangle (closest-point query on a BVH);
// - sign, by ray voting: `signRays` rays leave the voxel centre along fixed directions (a
//   Fibonacci sphere, signRayDirections()); a ray whose first hit is a back face
//   (dot(direction, cross(v1 - v0, v2 - v0)) > 0, i.e. counter-clockwise winding faces out)
//   votes "inside". The voxel is inside (negative) when more than insideFraction * signRays
//   rays vote inside. Misses and front-face hits count against.
//
// Counting over all rays rather than over hits is what keeps open meshes sane: inside a
// closed mesh every ray hits a back face; a single quad or plane covers at most half of the
// (antipodal) directions, so it stays positive on both sides (an unsigned, two-sided
// surface); a box without its lid is negative where its walls cover more than half the
// directions, which puts the sign change roughly in the plane of the missing lid.
#include "gi/bvh/bvh.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lumina::sdf {

struct SdfSettings {
    uint32_t resolution = 64;    // voxels along the longest axis, padding included (4..512)
    uint32_t padding = 2;        // empty voxels around the mesh bounds on every side
    uint32_t signRays = 32;      // ray-vote directions per voxel, even (2..256)
    float insideFraction = 0.5f; // inside when back-face votes > insideFraction * signRays
    uint32_t threads = 0;        // 0: std::thread::hardware_concurrency(); never changes the result
};

struct SdfBuildStats {
    double seconds = 0.0;  // wall time of the build (or of the cache load)
    uint64_t signRays = 0; // rays cast for the sign votes (early-out once the vote is decided)
    uint32_t triangles = 0;
    bool fromCache = false;
};

struct MeshSdf {
    glm::uvec3 dims{0};
    glm::vec3 volumeMin{0.0f}; // corner of voxel (0,0,0); voxel centres at volumeMin + (i + 0.5) * voxelSize
    float voxelSize = 0.0f;
    std::vector<float> distances; // signed, mesh units; x fastest, then y, then z
    bvh::Aabb meshBounds;
    SdfBuildStats stats;

    size_t voxelIndex(uint32_t x, uint32_t y, uint32_t z) const {
        return (size_t(z) * dims.y + y) * dims.x + x;
    }
    float at(uint32_t x, uint32_t y, uint32_t z) const { return distances[voxelIndex(x, y, z)]; }
    glm::vec3 voxelCentre(uint32_t x, uint32_t y, uint32_t z) const {
        return volumeMin + (glm::vec3(x, y, z) + 0.5f) * voxelSize;
    }
    glm::vec3 volumeMax() const { return volumeMin + glm::vec3(dims) * voxelSize; }
};

// Throws std::invalid_argument for an empty mesh, bad indices or settings.
MeshSdf buildMeshSdf(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                     const SdfSettings& settings = {});

struct MeshSdfInput {
    std::span<const glm::vec3> positions;
    std::span<const uint32_t> indices;
};

// Several meshes at once (a scene's): the triangle BVHs spread over the threads, then every
// mesh's z-slices from one shared queue, largest mesh first, so that no thread idles while
// another finishes a big mesh. Each result is bit for bit what buildMeshSdf gives (a slice's
// voxels never depend on the thread or on the slices before it); stats.seconds is the thread
// time spent on that mesh. Throws std::invalid_argument for an empty mesh or bad settings.
std::vector<MeshSdf> buildMeshSdfs(std::span<const MeshSdfInput> meshes, const SdfSettings& settings = {});

// Threads a build uses: settings.threads, or std::thread::hardware_concurrency() when 0.
uint32_t sdfBuildThreads(const SdfSettings& settings);

// The volume a build would use (dims, volumeMin, voxelSize; no distances).
MeshSdf sdfVolumeFor(const bvh::Aabb& meshBounds, const SdfSettings& settings);

// The vote directions: count / 2 points of a Fibonacci sphere (z_i = 1 - (2i + 1) / m,
// phi_i = (i + 0.5) * golden angle, m = count / 2), each followed by its opposite. Being
// antipodal pairs, any open half-space holds exactly half of them (none lies on the
// boundary plane), so no plane, quad or other surface seen from one side can ever collect
// more than half the votes: open surfaces stay positive unless they wrap around the voxel.
// Deterministic, so SDFs (and their cache keys) are reproducible.
std::vector<glm::vec3> signRayDirections(uint32_t count);

void validate(const SdfSettings& settings);

} // namespace lumina::sdf
