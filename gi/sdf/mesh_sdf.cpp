#include "gi/sdf/mesh_sdf.h"

#include "gi/bvh/bvh_query.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>

namespace lumina::sdf {
namespace {

constexpr uint32_t kMaxResolution = 512;
constexpr uint32_t kMaxSignRays = 256;
// The neighbour bound of the closest-point search is widened by this much (relative) so
// that rounding can never make it exclude the true nearest triangle.
constexpr float kNeighbourBoundSlack = 1e-4f;

// Ray votes of one voxel, stopping as soon as the outcome is certain (the result is the same
// as casting every ray).
bool isInside(const bvh::Bvh& bvh, const glm::vec3& p, const std::vector<glm::vec3>& directions,
              uint32_t insideVotesNeeded, uint64_t& raysCast) {
    const uint32_t n = uint32_t(directions.size());
    uint32_t inside = 0, outside = 0;
    for (const glm::vec3& d : directions) {
        ++raysCast;
        bvh::Ray ray;
        ray.origin = p;
        ray.direction = d;
        const bvh::RayHit hit = bvh::intersectClosest(bvh, ray);
        bool back = false;
        if (hit.hit()) {
            const gpu::BvhTriangle& t = bvh.triangles[hit.triangle];
            const glm::vec3 normal = glm::cross(glm::vec3(t.v1 - t.v0), glm::vec3(t.v2 - t.v0));
            back = glm::dot(d, normal) > 0.0f;
        }
        back ? ++inside : ++outside;
        if (inside >= insideVotesNeeded) {
            return true;
        }
        if (outside > n - insideVotesNeeded) {
            return false;
        }
    }
    return false;
}

} // namespace

void validate(const SdfSettings& settings) {
    if (settings.resolution < 4 || settings.resolution > kMaxResolution) {
        throw std::invalid_argument("SDF resolution " + std::to_string(settings.resolution) +
                                    " outside [4, 512]");
    }
    if (2 * settings.padding >= settings.resolution) {
        throw std::invalid_argument("SDF padding " + std::to_string(settings.padding) +
                                    " leaves no voxels of " + std::to_string(settings.resolution) +
                                    " for the mesh");
    }
    if (settings.signRays < 2 || settings.signRays > kMaxSignRays || settings.signRays % 2 != 0) {
        throw std::invalid_argument("SDF signRays " + std::to_string(settings.signRays) +
                                    " is not an even number in [2, 256]");
    }
    if (!(settings.insideFraction >= 0.0f && settings.insideFraction < 1.0f)) {
        throw std::invalid_argument("SDF insideFraction " + std::to_string(settings.insideFraction) +
                                    " outside [0, 1)");
    }
}

std::vector<glm::vec3> signRayDirections(uint32_t count) {
    const double goldenAngle = std::numbers::pi * (3.0 - std::sqrt(5.0));
    const uint32_t pairs = count / 2;
    std::vector<glm::vec3> directions;
    directions.reserve(2 * pairs);
    for (uint32_t i = 0; i < pairs; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / pairs;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = (i + 0.5) * goldenAngle;
        const glm::vec3 d(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
        directions.push_back(d);
        directions.push_back(-d);
    }
    return directions;
}

MeshSdf sdfVolumeFor(const bvh::Aabb& meshBounds, const SdfSettings& settings) {
    validate(settings);
    MeshSdf sdf;
    sdf.meshBounds = meshBounds;
    const glm::vec3 extent = meshBounds.size();
    int longest = 0;
    for (int a = 1; a < 3; ++a) {
        if (extent[a] > extent[longest]) {
            longest = a;
        }
    }
    const uint32_t interior = settings.resolution - 2 * settings.padding;
    // A flat or point-like mesh still gets a volume of finite, non-zero voxels.
    const float longestExtent = std::max(extent[longest], 1e-6f * (1.0f + glm::length(meshBounds.centre())));
    sdf.voxelSize = longestExtent / float(interior);
    for (int a = 0; a < 3; ++a) {
        const uint32_t inner =
            a == longest ? interior
                         : std::clamp(uint32_t(std::ceil(extent[a] / sdf.voxelSize - 1e-3f)), 1u, interior);
        sdf.dims[a] = inner + 2 * settings.padding;
    }
    sdf.volumeMin = meshBounds.centre() - 0.5f * glm::vec3(sdf.dims) * sdf.voxelSize;
    return sdf;
}

namespace {

// One mesh of a batch: its triangle BVH, its volume, and what its slices have added up.
struct MeshJob {
    bvh::Bvh bvh;
    MeshSdf sdf;
    std::atomic<uint64_t> raysCast{0};
    std::atomic<uint64_t> workNanoseconds{0}; // summed over the threads that worked on it
};

// Whether the vote of a voxel centre outside the mesh's bounds is decided without casting:
// beyond a face of the box, every direction pointing away from it (at least one of each
// antipodal pair) misses, so at most half the votes can say "inside"; with insideVotesNeeded
// above half, the voxel is outside, exactly what casting every ray would give.
bool surelyOutside(const bvh::Aabb& bounds, const glm::vec3& p, uint32_t rays, uint32_t insideVotesNeeded) {
    const bool beyondBox =
        glm::any(glm::lessThan(p, bounds.min)) || glm::any(glm::greaterThan(p, bounds.max));
    return beyondBox && 2 * insideVotesNeeded > rays;
}

// Voxels of z-slice z. Each row starts a fresh closest-point search, so that the result does
// not depend on which thread took which slice (or on what it built before).
void buildSlice(MeshJob& job, uint32_t z, const std::vector<glm::vec3>& directions,
                uint32_t insideVotesNeeded) {
    MeshSdf& sdf = job.sdf;
    uint64_t rays = 0;
    for (uint32_t y = 0; y < sdf.dims.y; ++y) {
        float previous = -1.0f;
        for (uint32_t x = 0; x < sdf.dims.x; ++x) {
            const glm::vec3 p = sdf.voxelCentre(x, y, z);
            // The previous voxel's distance plus the step bounds this one's.
            float bound = std::numeric_limits<float>::infinity();
            if (previous >= 0.0f) {
                const float r = (previous + sdf.voxelSize) * (1.0f + kNeighbourBoundSlack);
                bound = r * r;
            }
            bvh::ClosestPoint cp = bvh::closestPoint(job.bvh, p, bound);
            if (!cp.found()) {
                cp = bvh::closestPoint(job.bvh, p);
            }
            const float distance = std::sqrt(cp.distanceSquared);
            previous = distance;
            const bool inside =
                !surelyOutside(job.bvh.bounds, p, uint32_t(directions.size()), insideVotesNeeded) &&
                isInside(job.bvh, p, directions, insideVotesNeeded, rays);
            sdf.distances[sdf.voxelIndex(x, y, z)] = inside ? -distance : distance;
        }
    }
    job.raysCast += rays;
}

// Runs worker() on `count` threads (the caller's included) and rethrows the first exception.
template <typename Worker>
void runOnThreads(uint32_t count, Worker&& worker) {
    std::exception_ptr error;
    std::mutex errorMutex;
    auto guarded = [&] {
        try {
            worker();
        } catch (...) {
            std::lock_guard lock(errorMutex);
            if (!error) {
                error = std::current_exception();
            }
        }
    };
    std::vector<std::jthread> threads;
    for (uint32_t i = 1; i < count; ++i) {
        threads.emplace_back(guarded);
    }
    guarded();
    threads.clear(); // joins
    if (error) {
        std::rethrow_exception(error);
    }
}

uint64_t nanosecondsSince(std::chrono::steady_clock::time_point start) {
    return uint64_t(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start)
            .count());
}

} // namespace

uint32_t sdfBuildThreads(const SdfSettings& settings) {
    return settings.threads != 0 ? settings.threads : std::max(1u, std::thread::hardware_concurrency());
}

std::vector<MeshSdf> buildMeshSdfs(std::span<const MeshSdfInput> meshes, const SdfSettings& settings) {
    validate(settings);
    for (size_t m = 0; m < meshes.size(); ++m) {
        if (meshes[m].indices.empty()) {
            throw std::invalid_argument("buildMeshSdf: mesh " + std::to_string(m) +
                                        " of the batch has no triangles");
        }
    }
    const uint32_t threadCount = sdfBuildThreads(settings);
    std::vector<MeshJob> jobs(meshes.size());

    // Phase 1: one triangle BVH per mesh, meshes spread over the threads. Each BVH is built
    // single-threaded here (the threads are busy with other meshes); a BVH's layout does not
    // depend on its build's thread count.
    std::atomic<uint32_t> nextMesh{0};
    runOnThreads(std::min(threadCount, uint32_t(meshes.size())), [&] {
        for (uint32_t m = nextMesh++; m < meshes.size(); m = nextMesh++) {
            const auto start = std::chrono::steady_clock::now();
            bvh::BvhBuildSettings bvhSettings;
            bvhSettings.threads = meshes.size() == 1 ? threadCount : 1;
            MeshJob& job = jobs[m];
            job.bvh = bvh::buildBvh(meshes[m].positions, meshes[m].indices, bvhSettings);
            job.sdf = sdfVolumeFor(job.bvh.bounds, settings);
            job.sdf.stats.triangles = uint32_t(meshes[m].indices.size() / 3);
            job.sdf.distances.resize(size_t(job.sdf.dims.x) * job.sdf.dims.y * job.sdf.dims.z);
            job.workNanoseconds += nanosecondsSince(start);
        }
    });

    // Phase 2: every mesh's z-slices in one queue, largest mesh first, so that the tail of a
    // big mesh and the small ones keep every thread busy until the end.
    std::vector<uint32_t> order(meshes.size());
    for (uint32_t m = 0; m < order.size(); ++m) {
        order[m] = m;
    }
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return jobs[a].sdf.distances.size() > jobs[b].sdf.distances.size();
    });
    std::vector<std::pair<uint32_t, uint32_t>> slices; // (mesh, z)
    for (uint32_t m : order) {
        for (uint32_t z = 0; z < jobs[m].sdf.dims.z; ++z) {
            slices.emplace_back(m, z);
        }
    }
    const std::vector<glm::vec3> directions = signRayDirections(settings.signRays);
    const uint32_t insideVotesNeeded = std::min(
        settings.signRays, uint32_t(std::floor(settings.insideFraction * float(settings.signRays))) + 1);
    std::atomic<size_t> nextSlice{0};
    runOnThreads(uint32_t(std::min<size_t>(threadCount, slices.size())), [&] {
        for (size_t s = nextSlice++; s < slices.size(); s = nextSlice++) {
            const auto start = std::chrono::steady_clock::now();
            MeshJob& job = jobs[slices[s].first];
            try {
                buildSlice(job, slices[s].second, directions, insideVotesNeeded);
            } catch (...) {
                nextSlice = slices.size(); // the others stop early
                throw;
            }
            job.workNanoseconds += nanosecondsSince(start);
        }
    });

    std::vector<MeshSdf> out;
    out.reserve(jobs.size());
    for (MeshJob& job : jobs) {
        job.sdf.stats.signRays = job.raysCast;
        job.sdf.stats.seconds = double(job.workNanoseconds) * 1e-9;
        out.push_back(std::move(job.sdf));
    }
    return out;
}

MeshSdf buildMeshSdf(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                     const SdfSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    validate(settings);
    if (indices.empty()) {
        throw std::invalid_argument("buildMeshSdf: the mesh has no triangles");
    }
    const MeshSdfInput input{positions, indices};
    MeshSdf sdf = std::move(buildMeshSdfs(std::span(&input, 1), settings).front());
    sdf.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return sdf;
}

} // namespace lumina::sdf
