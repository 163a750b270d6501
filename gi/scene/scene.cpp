#include "gi/scene/scene.h"

#include <algorithm>
#include <cmath>

namespace lumina::scene {

Bounds transformBounds(const Bounds& local, const glm::mat4& transform) {
    Bounds out;
    if (local.empty()) {
        return out;
    }
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                          (corner & 4) ? local.max.z : local.min.z);
        out.extend(glm::vec3(transform * glm::vec4(p, 1.0f)));
    }
    return out;
}

std::vector<uint32_t> changedLights(std::span<const Light> before, std::span<const Light> after) {
    std::vector<uint32_t> changed;
    for (size_t i = 0; i < std::max(before.size(), after.size()); ++i) {
        if (i >= before.size() || i >= after.size() || before[i] != after[i]) {
            changed.push_back(uint32_t(i));
        }
    }
    return changed;
}

const char* lightTypeName(LightType type) {
    switch (type) {
    case LightType::Directional:
        return "directional";
    case LightType::Point:
        return "point";
    case LightType::Spot:
        return "spot";
    }
    return "unknown";
}

bool Scene::hasSky() const {
    if (skyEnvironment) {
        return std::any_of(skyEnvironment->radiance.begin(), skyEnvironment->radiance.end(),
                           [](const glm::vec3& texel) { return texel.x + texel.y + texel.z > 0.0f; });
    }
    return sky.x + sky.y + sky.z > 0.0f;
}

uint64_t Scene::triangleCount() const {
    uint64_t total = 0;
    for (const Instance& instance : instances) {
        total += meshes[instance.mesh].triangleCount();
    }
    return total;
}

uint64_t Scene::meshTriangleCount() const {
    uint64_t total = 0;
    for (const Mesh& mesh : meshes) {
        total += mesh.triangleCount();
    }
    return total;
}

uint64_t Scene::vertexCount() const {
    uint64_t total = 0;
    for (const Mesh& mesh : meshes) {
        total += mesh.positions.size();
    }
    return total;
}

Bounds Scene::worldBounds() const {
    Bounds out;
    for (const Instance& instance : instances) {
        out.extend(transformBounds(meshes[instance.mesh].bounds, instance.transform));
    }
    return out;
}

Camera frameBounds(const Bounds& bounds, float fovY) {
    Camera camera;
    camera.name = "framed";
    camera.fovY = fovY;
    const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : bounds.centre();
    const float radius = std::max(0.5f * glm::length(bounds.size()), 1e-3f);
    // Far enough that the bounding sphere fits the vertical field of view.
    const float distance = radius / std::sin(0.5f * fovY);
    camera.position = centre + glm::vec3(0.0f, 0.0f, distance);
    camera.forward = {0.0f, 0.0f, -1.0f};
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.nearPlane = std::max(distance - radius, distance * 1e-3f);
    camera.farPlane = distance + 2.0f * radius;
    return camera;
}

void finishCamera(Scene& scene) {
    const Bounds bounds = scene.worldBounds();
    if (!scene.cameraFromFile) {
        scene.camera = frameBounds(bounds, glm::radians(45.0f));
    }
    if (scene.camera.farPlane <= 0.0f) {
        float farthest = 0.0f;
        for (int corner = 0; corner < 8 && !bounds.empty(); ++corner) {
            const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                              (corner & 2) ? bounds.max.y : bounds.min.y,
                              (corner & 4) ? bounds.max.z : bounds.min.z);
            farthest = std::max(farthest, glm::length(p - scene.camera.position));
        }
        scene.camera.farPlane = std::max(2.0f * farthest, 2.0f * scene.camera.nearPlane);
    }
}

} // namespace lumina::scene
