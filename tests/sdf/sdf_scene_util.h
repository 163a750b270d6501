#pragma once
// Small multi-instance scenes for the scene SDF tests: meshes from tests/bvh/test_meshes.h
// placed with translation, rotation, uniform and non-uniform scale, and the world-space
// triangle BVH over all of them that the SDF traces are held against.
#include "gi/bvh/bvh.h"
#include "gi/scene/scene.h"
#include "tests/bvh/test_meshes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

namespace lumina::sdf::test {

inline scene::Mesh toSceneMesh(const lumina::test::Mesh& mesh, const char* name) {
    scene::Mesh out;
    out.name = name;
    out.positions = mesh.positions;
    out.indices = mesh.indices;
    out.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
    out.uvs.assign(mesh.positions.size(), glm::vec2(0.0f));
    out.submeshes.push_back({0, uint32_t(mesh.indices.size()), 0});
    for (const glm::vec3& p : mesh.positions) {
        out.bounds.extend(p);
    }
    return out;
}

inline glm::mat4 place(glm::vec3 at, float angle, glm::vec3 axis, glm::vec3 scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), at);
    m = glm::rotate(m, angle, glm::normalize(axis));
    return glm::scale(m, scale);
}

// A sphere, a box and an open box (no lid), seven instances between them, on a floor slab.
// Box b is scaled non-uniformly (1.5, 0.6, 1): the global SDF scales its distances by the
// smallest factor, a lower bound that makes far-field rays stop early beside it.
// Without `openBox` its instance places a closed box instead: an open mesh's SDF is signed by
// ray votes (gi/sdf/mesh_sdf.h), negative where its walls surround a point, so rays entering
// the open top stop at the lid's plane, which a triangle ray cast passes through.
inline scene::Scene makeTestScene(bool openBox = true) {
    scene::Scene s;
    s.name = "sdf_test_scene";
    s.meshes.push_back(toSceneMesh(lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 3), "sphere"));
    s.meshes.push_back(
        toSceneMesh(lumina::test::makeBox({-1.0f, -0.5f, -0.7f}, {1.0f, 0.5f, 0.7f}, 2), "box"));
    s.meshes.push_back(
        toSceneMesh(lumina::test::makeBox({-0.8f, -0.8f, -0.8f}, {0.8f, 0.8f, 0.8f}, 2, {3}), "open box"));
    s.meshes.push_back(
        toSceneMesh(lumina::test::makeBox({-4.0f, -0.3f, -3.5f}, {4.0f, 0.3f, 3.5f}, 4), "floor"));
    s.materials.push_back({});
    const glm::vec3 y(0, 1, 0);
    s.instances = {
        {0, place({0.0f, 0.0f, 0.0f}, 0.0f, y, glm::vec3(1.0f)), "sphere a"},
        {0, place({3.0f, 0.5f, 0.5f}, 0.7f, {1, 2, 3}, glm::vec3(0.6f)), "sphere b"},
        {1, place({-2.8f, 0.2f, 1.0f}, 0.5f, y, glm::vec3(1.0f)), "box a"},
        {1, place({1.0f, 0.2f, -2.5f}, 0.3f, {1, 0, 1}, {1.5f, 0.6f, 1.0f}), "box b (non-uniform)"},
        {openBox ? 2u : 1u, place({-1.5f, 0.0f, -2.0f}, 0.9f, y, glm::vec3(0.9f)), "open box"},
        {3, place({0.0f, -1.9f, 0.0f}, 0.0f, y, glm::vec3(1.0f)), "floor"},
        {0, place({2.0f, 1.8f, 2.4f}, 0.0f, y, glm::vec3(0.5f)), "sphere c"},
    };
    return s;
}

// World-space triangles of every instance, primId = instance index.
inline bvh::Bvh worldBvh(const scene::Scene& s) {
    std::vector<bvh::BuildTriangle> triangles;
    for (uint32_t i = 0; i < s.instances.size(); ++i) {
        const scene::Mesh& mesh = s.meshes[s.instances[i].mesh];
        const glm::mat4& m = s.instances[i].transform;
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            auto w = [&](uint32_t k) {
                return glm::vec3(m * glm::vec4(mesh.positions[mesh.indices[t + k]], 1.0f));
            };
            triangles.push_back({w(0), w(1), w(2), i});
        }
    }
    return bvh::buildBvh(triangles);
}

struct TestRay {
    glm::vec3 origin;
    glm::vec3 direction;
};

// Rays from a sphere around `bounds` aimed at random points inside it.
inline std::vector<TestRay> randomRays(const bvh::Aabb& bounds, uint32_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::vec3 centre = bounds.centre();
    const float radius = 0.5f * glm::length(bounds.size());
    std::vector<TestRay> rays(count);
    for (TestRay& ray : rays) {
        ray.origin = centre + 1.2f * radius * lumina::test::randomUnitVector(rng);
        const glm::vec3 target = bounds.min + bounds.size() * glm::vec3(u(rng), u(rng), u(rng));
        ray.direction = glm::normalize(target - ray.origin);
    }
    return rays;
}

} // namespace lumina::sdf::test
