// The city: a square grid of instanced buildings on a ground plane, for scaling runs. Eight
// building designs (2.5k triangles each on average, every window modelled) are placed,
// turned and stretched by a hash of the instance number, so generation is instant and
// deterministic; the default 1024 buildings draw about 2.55 million triangles.
#include "gi/scene/generators/generators.h"
#include "gi/scene/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace lumina::scene {

namespace {

constexpr uint32_t kDesigns = 8;
constexpr float kBlockSpacing = 32.0f; // metres between building centres
constexpr float kStoreyHeight = 3.2f;
constexpr float kWindowWidth = 1.6f;
constexpr float kWindowDepth = 0.25f;

enum CityMaterial : uint32_t { kGround, kConcrete, kBrick, kGlass, kRoof };

uint32_t hash(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// A building of `storeys` floors on a w x d footprint centred on the origin: a body, a
// window per 3 m of facade per floor (a glass pane over a sill), a parapet and a plant room
// on the roof.
Mesh buildingMesh(uint32_t design) {
    const uint32_t h = hash(design + 1);
    const float width = 12.0f + float(h % 4) * 2.5f;
    const float depth = 12.0f + float((h >> 4) % 4) * 2.5f;
    const uint32_t storeys = 6 + (h >> 8) % 8;
    const float height = float(storeys) * kStoreyHeight;
    MeshBuilder b("building " + std::to_string(design));
    b.material(design % 2 ? kBrick : kConcrete);
    b.box({-0.5f * width, 0.0f, -0.5f * depth}, {0.5f * width, height, 0.5f * depth}, false, 1u << 2);
    // Each facade in its own frame: origin at its left corner, `along` to the right,
    // `out` away from the building.
    struct Facade {
        glm::vec3 origin, along, out;
        float length;
    };
    const Facade facades[4] = {
        {{-0.5f * width, 0.0f, 0.5f * depth}, {1, 0, 0}, {0, 0, 1}, width},
        {{0.5f * width, 0.0f, -0.5f * depth}, {-1, 0, 0}, {0, 0, -1}, width},
        {{0.5f * width, 0.0f, 0.5f * depth}, {0, 0, -1}, {1, 0, 0}, depth},
        {{-0.5f * width, 0.0f, -0.5f * depth}, {0, 0, 1}, {-1, 0, 0}, depth},
    };
    // Sills first (the body's material), then all the glass: one submesh per material.
    for (const bool glass : {false, true}) {
        b.material(glass ? kGlass : (design % 2 ? kBrick : kConcrete));
        for (const Facade& f : facades) {
            const auto bays = uint32_t(f.length / 3.0f);
            const float pitch = f.length / float(bays);
            for (uint32_t s = 0; s < storeys; ++s) {
                for (uint32_t w = 0; w < bays; ++w) {
                    const glm::vec3 up(0.0f, 1.0f, 0.0f);
                    const glm::vec3 centre = f.origin + f.along * (pitch * (float(w) + 0.5f)) +
                                             up * (kStoreyHeight * (float(s) + 0.55f));
                    const glm::vec3 halfAlong = f.along * (0.5f * kWindowWidth);
                    if (glass) {
                        // Just proud of the wall, so it never fights the body for depth.
                        const glm::vec3 pane = centre + f.out * 0.02f;
                        b.quadFacingAwayFrom(pane - halfAlong - up * 0.9f, pane + halfAlong - up * 0.9f,
                                             pane + halfAlong + up * 0.9f, pane - halfAlong + up * 0.9f,
                                             centre - f.out);
                    } else {
                        const glm::vec3 a = centre - halfAlong - f.along * 0.1f - up * 1.1f;
                        const glm::vec3 c =
                            centre + halfAlong + f.along * 0.1f + f.out * kWindowDepth - up * 0.9f;
                        b.box(glm::min(a, c), glm::max(a, c));
                    }
                }
            }
        }
    }
    b.material(kRoof);
    b.box({-0.5f * width, height, -0.5f * depth}, {0.5f * width, height + 1.0f, -0.5f * depth + 0.3f}, false,
          1u << 2);
    b.box({-0.5f * width, height, 0.5f * depth - 0.3f}, {0.5f * width, height + 1.0f, 0.5f * depth}, false,
          1u << 2);
    b.box({-0.25f * width, height, -0.25f * depth}, {0.1f * width, height + 3.0f, 0.2f * depth}, false,
          1u << 2);
    return b.finish();
}

} // namespace

Scene makeCity(uint32_t buildings) {
    Scene scene;
    scene.name = "city";
    scene.generator = "city";
    scene.description = "a grid of " + std::to_string(buildings) + " instanced buildings, for scaling runs";
    scene.materials = {
        {.name = "ground", .baseColor = {0.3f, 0.3f, 0.3f, 1.0f}, .metallic = 0.0f},
        {.name = "concrete", .baseColor = {0.6f, 0.6f, 0.58f, 1.0f}, .metallic = 0.0f},
        {.name = "brick", .baseColor = {0.55f, 0.3f, 0.22f, 1.0f}, .metallic = 0.0f},
        {.name = "glass", .baseColor = {0.12f, 0.15f, 0.2f, 1.0f}, .metallic = 0.0f, .roughness = 0.1f},
        {.name = "roof", .baseColor = {0.4f, 0.4f, 0.42f, 1.0f}, .metallic = 0.0f},
    };
    const auto side = uint32_t(std::ceil(std::sqrt(double(std::max(buildings, 1u)))));
    const float extent = float(side) * kBlockSpacing;
    MeshBuilder ground("ground");
    ground.material(kGround);
    const float half = 0.5f * extent + kBlockSpacing;
    ground.quad({-half, 0.0f, -half}, {-half, 0.0f, half}, {half, 0.0f, half}, {half, 0.0f, -half});
    scene.meshes.push_back(ground.finish());
    for (uint32_t d = 0; d < kDesigns; ++d) {
        scene.meshes.push_back(buildingMesh(d));
    }
    scene.instances.reserve(buildings + 1);
    scene.instances.push_back({.mesh = 0, .transform = glm::mat4(1.0f), .name = "ground"});
    for (uint32_t i = 0; i < buildings; ++i) {
        const uint32_t h = hash(i * 2654435761u + 12345u);
        const glm::vec3 position((float(i % side) + 0.5f) * kBlockSpacing - 0.5f * extent, 0.0f,
                                 (float(i / side) + 0.5f) * kBlockSpacing - 0.5f * extent);
        glm::mat4 transform = glm::translate(glm::mat4(1.0f), position);
        transform = glm::rotate(transform, glm::radians(90.0f * float(h % 4)), {0.0f, 1.0f, 0.0f});
        // Taller or shorter by up to half, so the skyline varies between copies.
        transform = glm::scale(transform, {1.0f, 0.75f + 0.5f * float((h >> 8) % 256) / 255.0f, 1.0f});
        scene.instances.push_back({.mesh = 1 + (h >> 2) % kDesigns,
                                   .transform = transform,
                                   .name = "building " + std::to_string(i)});
    }

    scene.lights.push_back({.type = LightType::Directional,
                            .name = "sun",
                            .intensity = 10.0f,
                            .direction = glm::normalize(glm::vec3(0.4f, -0.8f, 0.3f))});
    const float reach = 0.5f * extent;
    scene.camera = {.name = "camera",
                    .position = {-reach, 0.35f * reach + 40.0f, -reach},
                    .forward = glm::normalize(glm::vec3(reach, -(0.35f * reach + 40.0f), reach)),
                    .fovY = glm::radians(50.0f),
                    .nearPlane = 0.5f,
                    .farPlane = 4.0f * extent + 500.0f};
    scene.camera.up = glm::normalize(
        glm::cross(glm::cross(scene.camera.forward, glm::vec3(0.0f, 1.0f, 0.0f)), scene.camera.forward));
    scene.cameraFromFile = true;
    scene.sky = {0.35f, 0.5f, 0.8f};
    scene.image = {1280, 720};
    return scene;
}

} // namespace lumina::scene
