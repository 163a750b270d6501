#include "gi/sdf/mesh_sdf.h"

#include "gi/bvh/bvh_query.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
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

MeshSdf buildMeshSdf(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                     const SdfSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    validate(settings);
    if (indices.empty()) {
        throw std::invalid_argument("buildMeshSdf: the mesh has no triangles");
    }
    bvh::BvhBuildSettings bvhSettings;
    bvhSettings.threads = settings.threads;
    const bvh::Bvh bvh = bvh::buildBvh(positions, indices, bvhSettings);

    MeshSdf sdf = sdfVolumeFor(bvh.bounds, settings);
    sdf.stats.triangles = uint32_t(indices.size() / 3);
    sdf.distances.resize(size_t(sdf.dims.x) * sdf.dims.y * sdf.dims.z);

    const std::vector<glm::vec3> directions = signRayDirections(settings.signRays);
    const uint32_t insideVotesNeeded = std::min(
        settings.signRays, uint32_t(std::floor(settings.insideFraction * float(settings.signRays))) + 1);

    // Workers take whole z-slices. Each row starts a fresh search so that the result does
    // not depend on which thread took which slice.
    std::atomic<uint32_t> nextSlice{0};
    std::atomic<uint64_t> raysCast{0};
    std::exception_ptr error;
    std::mutex errorMutex;
    auto worker = [&] {
        try {
            uint64_t rays = 0;
            for (uint32_t z = nextSlice++; z < sdf.dims.z; z = nextSlice++) {
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
                        bvh::ClosestPoint cp = bvh::closestPoint(bvh, p, bound);
                        if (!cp.found()) {
                            cp = bvh::closestPoint(bvh, p);
                        }
                        const float distance = std::sqrt(cp.distanceSquared);
                        previous = distance;
                        const bool inside = isInside(bvh, p, directions, insideVotesNeeded, rays);
                        sdf.distances[sdf.voxelIndex(x, y, z)] = inside ? -distance : distance;
                    }
                }
            }
            raysCast += rays;
        } catch (...) {
            std::lock_guard lock(errorMutex);
            error = std::current_exception();
            nextSlice = sdf.dims.z;
        }
    };
    const uint32_t threadCount =
        std::min(sdf.dims.z, settings.threads != 0 ? settings.threads
                                                   : std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> threads;
    for (uint32_t i = 1; i < threadCount; ++i) {
        threads.emplace_back(worker);
    }
    worker();
    for (std::thread& t : threads) {
        t.join();
    }
    if (error) {
        std::rethrow_exception(error);
    }
    sdf.stats.signRays = raysCast;
    sdf.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return sdf;
}

} // namespace lumina::sdf
