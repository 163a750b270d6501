#include "gi/bvh/bvh_query.h"

#include "shaders/common/ray_box.hlsli"
#include "shaders/common/ray_triangle.hlsli"

#include <vector>

namespace lumina::bvh {
namespace {

// A traversal stack on the C++ stack for every tree the GPU can traverse too, on the heap
// for deeper (pathological) trees.
template <typename Entry>
class TraversalStack {
public:
    explicit TraversalStack(uint32_t depth) {
        if (depth > kLocal) {
            heap_.resize(depth);
            data_ = heap_.data();
        }
    }
    void push(const Entry& e) { data_[size_++] = e; }
    Entry pop() { return data_[--size_]; }
    bool empty() const { return size_ == 0; }

private:
    static constexpr uint32_t kLocal = 64;
    Entry local_[kLocal];
    std::vector<Entry> heap_;
    Entry* data_ = local_;
    uint32_t size_ = 0;
};

struct RayEntry {
    uint32_t node;
    float tNear;
};

struct PointEntry {
    uint32_t node;
    float distanceSquared;
};

float boxDistanceSquared(const glm::vec4& boxMin, const glm::vec4& boxMax, const glm::vec3& p) {
    const glm::vec3 d = glm::max(glm::max(glm::vec3(boxMin) - p, glm::vec3(0.0f)), p - glm::vec3(boxMax));
    return glm::dot(d, d);
}

template <bool AnyHit>
RayHit traverse(const Bvh& bvh, const Ray& ray) {
    RayHit hit;
    if (bvh.nodes.empty()) {
        return hit;
    }
    const gpu::WatertightRay wray = gpu::makeWatertightRay(ray.origin, ray.direction);
    const glm::vec3 invDir = gpu::safeReciprocal3(ray.direction);
    float tMax = ray.tMax;
    auto boxEntry = [&](uint32_t node) {
        const gpu::BvhNode& n = bvh.nodes[node];
        return gpu::intersectBox(ray.origin, invDir, glm::vec3(n.minAndIndex), glm::vec3(n.maxAndCount),
                                 ray.tMin, tMax);
    };
    const float rootEntry = boxEntry(0);
    if (rootEntry < 0.0f) {
        return hit;
    }
    TraversalStack<RayEntry> stack(bvh.depth);
    stack.push({0, rootEntry});
    while (!stack.empty()) {
        const RayEntry entry = stack.pop();
        if (entry.tNear > tMax) {
            continue; // a closer hit was found after this node was pushed
        }
        uint32_t node = entry.node;
        for (;;) {
            const gpu::BvhNode& n = bvh.nodes[node];
            if (isLeaf(n)) {
                const uint32_t first = nodeIndex(n);
                const uint32_t end = first + nodeCount(n);
                for (uint32_t i = first; i < end; ++i) {
                    const gpu::BvhTriangle& tri = bvh.triangles[i];
                    float t;
                    glm::vec2 bary;
                    if (gpu::intersectTriangleWatertight(wray, glm::vec3(tri.v0), glm::vec3(tri.v1),
                                                         glm::vec3(tri.v2), ray.tMin, tMax, t, bary)) {
                        tMax = t;
                        hit = {t, bary, primId(tri), i};
                        if constexpr (AnyHit) {
                            return hit;
                        }
                    }
                }
                break;
            }
            const uint32_t left = node + 1;
            const uint32_t right = nodeIndex(n);
            const float tLeft = boxEntry(left);
            const float tRight = boxEntry(right);
            if (tLeft >= 0.0f && tRight >= 0.0f) {
                const bool leftFirst = tLeft <= tRight;
                stack.push(leftFirst ? RayEntry{right, tRight} : RayEntry{left, tLeft});
                node = leftFirst ? left : right;
            } else if (tLeft >= 0.0f) {
                node = left;
            } else if (tRight >= 0.0f) {
                node = right;
            } else {
                break;
            }
        }
    }
    return hit;
}

float safeRatio(float num, float den) {
    return den != 0.0f ? num / den : 0.0f;
}

} // namespace

RayHit intersectClosest(const Bvh& bvh, const Ray& ray) {
    return traverse<false>(bvh, ray);
}

bool intersectAny(const Bvh& bvh, const Ray& ray) {
    return traverse<true>(bvh, ray).hit();
}

glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c, glm::vec2& barycentrics) {
    // Voronoi regions of the vertices, then of the edges, then the face. Divisions are
    // guarded so that degenerate (zero-area or zero-length-edge) triangles give a point of
    // the triangle instead of a NaN.
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) {
        barycentrics = {0.0f, 0.0f};
        return a;
    }
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) {
        barycentrics = {1.0f, 0.0f};
        return b;
    }
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
        const float v = safeRatio(d1, d1 - d3);
        barycentrics = {v, 0.0f};
        return a + v * ab;
    }
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) {
        barycentrics = {0.0f, 1.0f};
        return c;
    }
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
        const float w = safeRatio(d2, d2 - d6);
        barycentrics = {0.0f, w};
        return a + w * ac;
    }
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
        const float w = safeRatio(d4 - d3, (d4 - d3) + (d5 - d6));
        barycentrics = {1.0f - w, w};
        return b + w * (c - b);
    }
    const float denom = va + vb + vc;
    if (!(denom > 0.0f)) {
        // Degenerate triangle seen as a face: the nearest of its three edges is the answer.
        glm::vec3 best = a;
        float bestD2 = std::numeric_limits<float>::infinity();
        const glm::vec3 ends[3][2] = {{a, b}, {b, c}, {c, a}};
        const glm::vec2 weights[3][2] = {{{0, 0}, {1, 0}}, {{1, 0}, {0, 1}}, {{0, 1}, {0, 0}}};
        for (int e = 0; e < 3; ++e) {
            const glm::vec3 d = ends[e][1] - ends[e][0];
            const float s = glm::clamp(safeRatio(glm::dot(p - ends[e][0], d), glm::dot(d, d)), 0.0f, 1.0f);
            const glm::vec3 q = ends[e][0] + s * d;
            const float d2q = glm::dot(q - p, q - p);
            if (d2q < bestD2) {
                bestD2 = d2q;
                best = q;
                barycentrics = glm::mix(weights[e][0], weights[e][1], s);
            }
        }
        return best;
    }
    const float v = vb / denom, w = vc / denom;
    barycentrics = {v, w};
    return a + ab * v + ac * w;
}

ClosestPoint closestPoint(const Bvh& bvh, const glm::vec3& p, float maxDistanceSquared) {
    ClosestPoint best;
    best.distanceSquared = maxDistanceSquared;
    if (bvh.nodes.empty()) {
        return best;
    }
    auto boxD2 = [&](uint32_t node) {
        return boxDistanceSquared(bvh.nodes[node].minAndIndex, bvh.nodes[node].maxAndCount, p);
    };
    const float rootD2 = boxD2(0);
    if (rootD2 > best.distanceSquared) {
        return best;
    }
    TraversalStack<PointEntry> stack(bvh.depth);
    stack.push({0, rootD2});
    while (!stack.empty()) {
        const PointEntry entry = stack.pop();
        if (entry.distanceSquared > best.distanceSquared) {
            continue;
        }
        uint32_t node = entry.node;
        for (;;) {
            const gpu::BvhNode& n = bvh.nodes[node];
            if (isLeaf(n)) {
                const uint32_t first = nodeIndex(n);
                const uint32_t end = first + nodeCount(n);
                for (uint32_t i = first; i < end; ++i) {
                    const gpu::BvhTriangle& tri = bvh.triangles[i];
                    glm::vec2 bary;
                    const glm::vec3 q = closestPointOnTriangle(p, glm::vec3(tri.v0), glm::vec3(tri.v1),
                                                               glm::vec3(tri.v2), bary);
                    const float d2 = glm::dot(q - p, q - p);
                    if (d2 < best.distanceSquared || (d2 == best.distanceSquared && !best.found())) {
                        best = {q, d2, bary, primId(tri), i};
                    }
                }
                break;
            }
            const uint32_t left = node + 1;
            const uint32_t right = nodeIndex(n);
            const float dLeft = boxD2(left);
            const float dRight = boxD2(right);
            const bool leftOk = dLeft <= best.distanceSquared;
            const bool rightOk = dRight <= best.distanceSquared;
            if (leftOk && rightOk) {
                const bool leftFirst = dLeft <= dRight;
                stack.push(leftFirst ? PointEntry{right, dRight} : PointEntry{left, dLeft});
                node = leftFirst ? left : right;
            } else if (leftOk) {
                node = left;
            } else if (rightOk) {
                node = right;
            } else {
                break;
            }
        }
    }
    return best;
}

} // namespace lumina::bvh
