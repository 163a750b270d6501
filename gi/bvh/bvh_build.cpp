#include "gi/bvh/bvh.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

namespace lumina::bvh {
namespace {

// Subtrees smaller than this are built on the calling thread: below it a thread costs
// more than it saves.
constexpr uint32_t kParallelMinTriangles = 16 * 1024;
constexpr uint32_t kMaxBins = 64;
// Node boxes are widened by this fraction of the largest coordinate (2^-20, about 8 ulp there).
constexpr float kBoundsMargin = 1.0f / (1 << 20);

struct BuildNode {
    Aabb bounds;
    uint32_t index = 0; // second child (interior) or first triangle (leaf)
    uint32_t count = 0; // triangles, 0 for interior
};

// Trivially constructible (unlike Aabb), so that a stack array of bins costs nothing until
// the bins in use are cleared.
struct Bin {
    glm::vec3 boundsMin, boundsMax, centroidMin, centroidMax;
    uint32_t count;

    void clear() {
        boundsMin = centroidMin = glm::vec3(std::numeric_limits<float>::max());
        boundsMax = centroidMax = glm::vec3(-std::numeric_limits<float>::max());
        count = 0;
    }
    void add(const Aabb& box, const glm::vec3& centroid) {
        boundsMin = glm::min(boundsMin, box.min);
        boundsMax = glm::max(boundsMax, box.max);
        centroidMin = glm::min(centroidMin, centroid);
        centroidMax = glm::max(centroidMax, centroid);
        ++count;
    }
    Aabb bounds() const { return {boundsMin, boundsMax}; }
    Aabb centroids() const { return {centroidMin, centroidMax}; }
};

struct Split {
    int axis = -1;
    uint32_t bin = 0; // triangles in bins [0, bin) go left
    uint32_t binCount = 0;
    float scale = 0.0f; // bins per unit of centroid extent along the axis
    float cost = std::numeric_limits<float>::infinity();
    Aabb leftBounds, rightBounds, leftCentroids, rightCentroids;
};

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Appends `nodes` (built with indices relative to their own vector) at `offset`.
void appendShifted(std::vector<BuildNode>& out, const std::vector<BuildNode>& nodes, uint32_t offset) {
    for (BuildNode node : nodes) {
        if (node.count == 0) {
            node.index += offset;
        }
        out.push_back(node);
    }
}

class Builder {
public:
    Builder(std::span<const BuildTriangle> triangles, const BvhBuildSettings& settings)
        : triangles_(triangles), settings_(settings) {
        const uint32_t threads =
            settings.threads != 0 ? settings.threads : std::max(1u, std::thread::hardware_concurrency());
        // One level more than the thread count needs, so that uneven halves still keep every core busy.
        parallelDepth_ = threads > 1 ? uint32_t(std::bit_width(threads - 1)) + 1 : 0;
        bounds_.resize(triangles.size());
        centroids_.resize(triangles.size());
        order_.resize(triangles.size());
        for (uint32_t i = 0; i < triangles.size(); ++i) {
            const BuildTriangle& t = triangles[i];
            if (!isFinite(t.v0) || !isFinite(t.v1) || !isFinite(t.v2)) {
                throw std::invalid_argument("buildBvh: triangle " + std::to_string(i) + " (primId " +
                                            std::to_string(t.primId) + ") has a non-finite vertex");
            }
            Aabb box;
            box.extend(t.v0);
            box.extend(t.v1);
            box.extend(t.v2);
            bounds_[i] = box;
            centroids_[i] = box.centre();
            order_[i] = i;
        }
    }

    Bvh build() {
        Bvh bvh;
        if (triangles_.empty()) {
            return bvh;
        }
        Aabb bounds, centroids;
        for (uint32_t i = 0; i < triangles_.size(); ++i) {
            bounds.extend(bounds_[i]);
            centroids.extend(centroids_[i]);
        }
        std::vector<BuildNode> nodes;
        nodes.reserve(2 * triangles_.size() / std::max(1u, settings_.maxLeafSize / 2) + 1);
        bvh.depth = buildRange(0, uint32_t(triangles_.size()), bounds, centroids, nodes, 0);
        bvh.bounds = bounds;

        // Every box grows by the same small margin, so that an axis-parallel ray lying exactly
        // in a box's face plane (along a wall) still enters it: its slab distance there is
        // 0 times the huge reciprocal, 0 rather than the infinite span it should be. Equal
        // margins keep children inside their parents.
        const glm::vec3 extent = glm::max(glm::abs(bounds.min), glm::abs(bounds.max));
        const float magnitude = std::max(std::max(extent.x, extent.y), extent.z);
        const glm::vec3 margin(std::max(kBoundsMargin * magnitude, std::numeric_limits<float>::min()));
        bvh.nodes.resize(nodes.size());
        for (size_t i = 0; i < nodes.size(); ++i) {
            const BuildNode& n = nodes[i];
            bvh.nodes[i].minAndIndex = glm::vec4(n.bounds.min - margin, gpu::asfloat(n.index));
            bvh.nodes[i].maxAndCount = glm::vec4(n.bounds.max + margin, gpu::asfloat(n.count));
        }
        bvh.triangles.resize(triangles_.size());
        for (size_t i = 0; i < order_.size(); ++i) {
            const BuildTriangle& t = triangles_[order_[i]];
            bvh.triangles[i].v0 = glm::vec4(t.v0, gpu::asfloat(t.primId));
            bvh.triangles[i].v1 = glm::vec4(t.v1, 0.0f);
            bvh.triangles[i].v2 = glm::vec4(t.v2, 0.0f);
        }
        return bvh;
    }

private:
    // Builds [begin, end) of order_ into `out` depth-first; returns the subtree's depth.
    uint32_t buildRange(uint32_t begin, uint32_t end, const Aabb& bounds, const Aabb& centroids,
                        std::vector<BuildNode>& out, uint32_t depth) {
        const uint32_t count = end - begin;
        const uint32_t self = uint32_t(out.size());
        out.push_back({bounds, begin, count});
        if (count == 1) {
            return 1;
        }

        const Split split = findSplit(begin, end, bounds, centroids);
        const float leafCost = settings_.intersectionCost * float(count);
        if (count <= settings_.maxLeafSize && (split.axis < 0 || leafCost <= split.cost)) {
            return 1;
        }

        uint32_t mid;
        Aabb leftBounds, rightBounds, leftCentroids, rightCentroids;
        if (split.axis >= 0) {
            mid = partition(begin, end, centroids, split);
            leftBounds = split.leftBounds;
            rightBounds = split.rightBounds;
            leftCentroids = split.leftCentroids;
            rightCentroids = split.rightCentroids;
        } else {
            // Every centroid coincides: no plane separates them, so halve the range.
            mid = begin + count / 2;
            for (uint32_t i = begin; i < end; ++i) {
                (i < mid ? leftBounds : rightBounds).extend(bounds_[order_[i]]);
            }
            leftCentroids = rightCentroids = centroids;
        }

        out[self].count = 0;
        uint32_t leftDepth = 0, rightDepth = 0;
        if (depth < parallelDepth_ && count >= kParallelMinTriangles) {
            std::vector<BuildNode> leftNodes, rightNodes;
            std::exception_ptr leftError;
            std::thread leftThread([&] {
                try {
                    leftDepth = buildRange(begin, mid, leftBounds, leftCentroids, leftNodes, depth + 1);
                } catch (...) {
                    leftError = std::current_exception();
                }
            });
            std::exception_ptr rightError;
            try {
                rightDepth = buildRange(mid, end, rightBounds, rightCentroids, rightNodes, depth + 1);
            } catch (...) {
                rightError = std::current_exception();
            }
            leftThread.join();
            if (leftError || rightError) {
                std::rethrow_exception(leftError ? leftError : rightError);
            }
            appendShifted(out, leftNodes, uint32_t(out.size()));
            out[self].index = uint32_t(out.size());
            appendShifted(out, rightNodes, uint32_t(out.size()));
        } else {
            leftDepth = buildRange(begin, mid, leftBounds, leftCentroids, out, depth + 1);
            out[self].index = uint32_t(out.size());
            rightDepth = buildRange(mid, end, rightBounds, rightCentroids, out, depth + 1);
        }
        return 1 + std::max(leftDepth, rightDepth);
    }

    static uint32_t binOf(const glm::vec3& centroid, int axis, float origin, float scale, uint32_t binCount) {
        const float f = (centroid[axis] - origin) * scale;
        return std::min(uint32_t(f), binCount - 1);
    }

    // Binned SAH over the three axes in one pass over the triangles. Small ranges use fewer
    // bins (as many as triangles, at least 4): their split quality hardly changes, and
    // clearing and sweeping 3 x 32 bins would dominate the cost of the lowest levels.
    Split findSplit(uint32_t begin, uint32_t end, const Aabb& bounds, const Aabb& centroids) const {
        Split best;
        const uint32_t count = end - begin;
        const uint32_t binCount = std::min(settings_.binCount, std::max(4u, count));
        const float parentArea = bounds.halfArea();
        bool active[3];
        float scale[3];
        Bin bins[3][kMaxBins];
        for (int axis = 0; axis < 3; ++axis) {
            // An extent so small that binCount / extent overflows cannot be binned either.
            scale[axis] = float(binCount) / (centroids.max[axis] - centroids.min[axis]);
            active[axis] = centroids.max[axis] > centroids.min[axis] && std::isfinite(scale[axis]);
            if (!active[axis]) {
                scale[axis] = 0.0f; // every triangle lands in bin 0 (never NaN from 0 * inf)
            }
            for (uint32_t b = 0; b < binCount; ++b) {
                bins[axis][b].clear();
            }
        }
        for (uint32_t i = begin; i < end; ++i) {
            const uint32_t prim = order_[i];
            for (int axis = 0; axis < 3; ++axis) {
                bins[axis][binOf(centroids_[prim], axis, centroids.min[axis], scale[axis], binCount)].add(
                    bounds_[prim], centroids_[prim]);
            }
        }
        for (int axis = 0; axis < 3; ++axis) {
            if (!active[axis]) {
                continue;
            }
            // Right-to-left sweep stores the right side of every plane; left-to-right evaluates.
            float rightArea[kMaxBins];
            uint32_t rightCount[kMaxBins];
            Aabb right;
            uint32_t rightN = 0;
            for (uint32_t b = binCount - 1; b > 0; --b) {
                right.extend(bins[axis][b].bounds());
                rightN += bins[axis][b].count;
                rightArea[b] = right.halfArea();
                rightCount[b] = rightN;
            }
            Aabb left;
            uint32_t leftN = 0;
            for (uint32_t b = 1; b < binCount; ++b) {
                left.extend(bins[axis][b - 1].bounds());
                leftN += bins[axis][b - 1].count;
                if (leftN == 0 || rightCount[b] == 0) {
                    continue;
                }
                const float cost = parentArea > 0.0f
                                       ? settings_.traversalCost + settings_.intersectionCost *
                                                                       (left.halfArea() * float(leftN) +
                                                                        rightArea[b] * float(rightCount[b])) /
                                                                       parentArea
                                       : settings_.traversalCost + settings_.intersectionCost * float(count);
                if (cost < best.cost) {
                    best.cost = cost;
                    best.axis = axis;
                    best.bin = b;
                }
            }
        }
        if (best.axis >= 0) {
            best.binCount = binCount;
            best.scale = scale[best.axis];
            for (uint32_t b = 0; b < binCount; ++b) {
                const Bin& bin = bins[best.axis][b];
                (b < best.bin ? best.leftBounds : best.rightBounds).extend(bin.bounds());
                (b < best.bin ? best.leftCentroids : best.rightCentroids).extend(bin.centroids());
            }
        }
        return best;
    }

    uint32_t partition(uint32_t begin, uint32_t end, const Aabb& centroids, const Split& split) {
        auto* first = order_.data() + begin;
        auto* middle = std::partition(first, order_.data() + end, [&](uint32_t prim) {
            return binOf(centroids_[prim], split.axis, centroids.min[split.axis], split.scale,
                         split.binCount) < split.bin;
        });
        return begin + uint32_t(middle - first);
    }

    std::span<const BuildTriangle> triangles_;
    BvhBuildSettings settings_;
    uint32_t parallelDepth_ = 0;
    std::vector<Aabb> bounds_;
    std::vector<glm::vec3> centroids_;
    std::vector<uint32_t> order_;
};

void validate(const BvhBuildSettings& settings) {
    if (settings.binCount < 2 || settings.binCount > kMaxBins) {
        throw std::invalid_argument("buildBvh: binCount " + std::to_string(settings.binCount) +
                                    " outside [2, 64]");
    }
    if (settings.maxLeafSize < 1) {
        throw std::invalid_argument("buildBvh: maxLeafSize must be at least 1");
    }
    if (!(settings.traversalCost >= 0.0f) || !(settings.intersectionCost > 0.0f)) {
        throw std::invalid_argument("buildBvh: SAH costs must be >= 0 (traversal) and > 0 (intersection)");
    }
}

} // namespace

Bvh buildBvh(std::span<const BuildTriangle> triangles, const BvhBuildSettings& settings) {
    validate(settings);
    if (triangles.size() >= std::numeric_limits<uint32_t>::max() / 2) {
        throw std::invalid_argument("buildBvh: " + std::to_string(triangles.size()) +
                                    " triangles is too many");
    }
    return Builder(triangles, settings).build();
}

Bvh buildBvh(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
             const BvhBuildSettings& settings) {
    if (indices.size() % 3 != 0) {
        throw std::invalid_argument("buildBvh: index count " + std::to_string(indices.size()) +
                                    " is not a multiple of 3");
    }
    std::vector<BuildTriangle> triangles(indices.size() / 3);
    for (size_t t = 0; t < triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            if (indices[3 * t + k] >= positions.size()) {
                throw std::invalid_argument("buildBvh: index " + std::to_string(indices[3 * t + k]) +
                                            " of triangle " + std::to_string(t) + " is out of range (" +
                                            std::to_string(positions.size()) + " positions)");
            }
        }
        triangles[t] = {positions[indices[3 * t]], positions[indices[3 * t + 1]],
                        positions[indices[3 * t + 2]], uint32_t(t)};
    }
    return buildBvh(triangles, settings);
}

double sahCost(const Bvh& bvh, const BvhBuildSettings& settings) {
    if (bvh.nodes.empty()) {
        return 0.0;
    }
    const double rootArea = nodeBounds(bvh.nodes[0]).halfArea();
    if (rootArea <= 0.0) {
        return settings.intersectionCost * double(bvh.triangles.size());
    }
    double cost = 0.0;
    for (const gpu::BvhNode& node : bvh.nodes) {
        const double ratio = nodeBounds(node).halfArea() / rootArea;
        cost += isLeaf(node) ? settings.intersectionCost * nodeCount(node) * ratio
                             : settings.traversalCost * ratio;
    }
    return cost;
}

} // namespace lumina::bvh
