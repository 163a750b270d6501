// The atrium: a stand-in for Sponza, generated in code. A 32 m x 20 m courtyard open to the
// sky, two storeys of arcades along its long sides (columns, arches, a balustrade upstairs),
// coloured drapes hanging in the upper arches, banners on the end walls, and a sun. About
// 200k triangles, most of them instanced columns, arches and drapes.
#include "gi/scene/generators/generators.h"
#include "gi/scene/mesh_builder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

namespace lumina::scene {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Layout, metres. The courtyard is |z| < kArcadeZ; galleries run from there to the walls.
constexpr float kHalfLength = 16.0f;
constexpr float kHalfWidth = 10.0f;
constexpr float kArcadeZ = 6.0f;
constexpr float kStoreyHeight = 6.0f;
constexpr int kStoreys = 2;
constexpr float kBaySpacing = 2.0f;
constexpr float kColumnTop = 4.0f;  // springing line of the arches
constexpr float kArchRadius = 0.7f; // clear half-span between capitals
constexpr float kArchDepth = 0.5f;  // thickness of the arcade wall
constexpr float kSlabThickness = 0.5f;
constexpr float kWallThickness = 0.5f;

enum AtriumMaterial : uint32_t { kStone, kTileLight, kTileDark, kPlaster, kRed, kGreen, kBlue, kBronze };

// The column: plinth, smooth shaft, capital; its axis on local x = z = 0.
Mesh columnMesh() {
    MeshBuilder b("column");
    b.material(kStone);
    b.box({-0.3f, 0.0f, -0.3f}, {0.3f, 0.3f, 0.3f}, false, 1u << 2);
    b.cylinder({0.0f, 0.3f, 0.0f}, 0.25f, kColumnTop - 0.6f, 32, 20);
    b.box({-0.3f, kColumnTop - 0.3f, -0.3f}, {0.3f, kColumnTop, 0.3f});
    return b.finish();
}

// The wall above one bay, x in [-1, 1], from the springing line up to the next floor, with
// a semicircular opening of kArchRadius; its faces at z = -/+ kArchDepth/2, and the soffit.
// Local y = 0 is the springing line.
Mesh archMesh() {
    MeshBuilder b("arch");
    b.material(kStone);
    constexpr int kArcSegments = 32;
    const float halfSpan = 0.5f * kBaySpacing;
    const float height = kStoreyHeight - kColumnTop;
    // Angles sampled along the opening, plus those of the wall's top corners so that the
    // strip between arc and outline keeps them.
    std::vector<float> angles;
    for (int i = 0; i <= kArcSegments; ++i) {
        angles.push_back(kPi * float(i) / float(kArcSegments));
    }
    const float corner = std::atan2(height, halfSpan);
    angles.push_back(corner);
    angles.push_back(kPi - corner);
    std::sort(angles.begin(), angles.end());
    // Where the ray from the arc's centre at `angle` leaves the wall's outline.
    auto outline = [&](float angle) {
        const glm::vec2 d(std::cos(angle), std::sin(angle));
        const float tx = std::abs(d.x) > 1e-6f ? halfSpan / std::abs(d.x) : 1e9f;
        const float ty = d.y > 1e-6f ? height / d.y : 1e9f;
        return d * std::min(tx, ty);
    };
    for (const float side : {-1.0f, 1.0f}) {
        const float z = side * 0.5f * kArchDepth;
        for (size_t i = 0; i + 1 < angles.size(); ++i) {
            const glm::vec2 a0 = kArchRadius * glm::vec2(std::cos(angles[i]), std::sin(angles[i]));
            const glm::vec2 a1 = kArchRadius * glm::vec2(std::cos(angles[i + 1]), std::sin(angles[i + 1]));
            const glm::vec2 o0 = outline(angles[i]), o1 = outline(angles[i + 1]);
            b.quadFacingAwayFrom({a0, z}, {a1, z}, {o1, z}, {o0, z}, {0.0f, 0.0f, 0.0f});
        }
    }
    for (size_t i = 0; i + 1 < angles.size(); ++i) {
        const glm::vec2 a0 = kArchRadius * glm::vec2(std::cos(angles[i]), std::sin(angles[i]));
        const glm::vec2 a1 = kArchRadius * glm::vec2(std::cos(angles[i + 1]), std::sin(angles[i + 1]));
        const float z = 0.5f * kArchDepth;
        // The soffit faces the opening's centre, away from a point beyond it.
        const glm::vec2 beyond = (a0 + a1) * 2.0f;
        b.quadFacingAwayFrom({a0, -z}, {a1, -z}, {a1, z}, {a0, z}, {beyond, 0.0f});
    }
    // The top, so that the wall is closed to the sky (its ends meet the next bay's).
    const float z = 0.5f * kArchDepth;
    b.quadFacingAwayFrom({-halfSpan, height, -z}, {halfSpan, height, -z}, {halfSpan, height, z},
                         {-halfSpan, height, z}, {0.0f, 0.0f, 0.0f});
    return b.finish();
}

// Upstairs between two columns: two rails and seven balusters.
Mesh balustradeMesh() {
    MeshBuilder b("balustrade");
    b.material(kBronze);
    b.box({-0.7f, 0.0f, -0.08f}, {0.7f, 0.1f, 0.08f});
    b.box({-0.7f, 0.9f, -0.08f}, {0.7f, 1.0f, 0.08f});
    for (int i = 0; i < 7; ++i) {
        b.cylinder({-0.6f + 0.2f * float(i), 0.1f, 0.0f}, 0.04f, 0.8f, 12, 4);
    }
    return b.finish();
}

// Cloth hanging from a rod at local y = 0 down to -length, facing -z, folded.
Mesh clothMesh(const char* name, uint32_t material, float width, float length, uint32_t nu, uint32_t nv,
               float folds) {
    MeshBuilder b(name);
    b.material(material);
    b.grid({-0.5f * width, 0.0f, 0.0f}, {width, 0.0f, 0.0f}, {0.0f, -length, 0.0f}, nu, nv,
           [&](float s, float t) {
               const float amplitude = 0.03f + 0.07f * t;
               const float fold = amplitude * std::sin(2.0f * kPi * folds * s);
               const float billow = -0.08f * t * std::sin(kPi * s);
               return glm::vec3(0.0f, 0.0f, fold + billow);
           });
    return b.finish();
}

// Floor tiles, outer walls, gallery floors and roofs.
Mesh structureMesh() {
    MeshBuilder b("structure");
    // A chequerboard of 1 m tiles, light ones first then dark: one submesh each.
    constexpr float kTile = 1.0f;
    for (const uint32_t material : {kTileLight, kTileDark}) {
        b.material(material);
        for (int i = 0; i < int(2.0f * kHalfLength / kTile); ++i) {
            for (int j = 0; j < int(2.0f * kHalfWidth / kTile); ++j) {
                if (uint32_t((i + j) & 1) != (material == kTileDark ? 1u : 0u)) {
                    continue;
                }
                const float x = -kHalfLength + kTile * float(i), z = -kHalfWidth + kTile * float(j);
                b.quad({x, 0.0f, z}, {x, 0.0f, z + kTile}, {x + kTile, 0.0f, z + kTile},
                       {x + kTile, 0.0f, z});
            }
        }
    }
    b.material(kPlaster);
    const float top = kStoreyHeight * kStoreys;
    const float t = kWallThickness;
    for (const float side : {-1.0f, 1.0f}) {
        // Long walls behind the galleries, end walls across the courtyard.
        const float z0 = side > 0 ? kHalfWidth : -kHalfWidth - t;
        b.box({-kHalfLength - t, 0.0f, z0}, {kHalfLength + t, top, z0 + t}, false, 1u << 2);
        const float x0 = side > 0 ? kHalfLength : -kHalfLength - t;
        b.box({x0, 0.0f, -kHalfWidth}, {x0 + t, top, kHalfWidth}, false, (1u << 2) | (1u << 4) | (1u << 5));
    }
    b.material(kStone);
    for (int storey = 1; storey <= kStoreys; ++storey) {
        const float y = kStoreyHeight * float(storey);
        for (const float side : {-1.0f, 1.0f}) {
            const float zNear = side * (kArcadeZ + 0.5f * kArchDepth), zFar = side * kHalfWidth;
            b.box({-kHalfLength, y - kSlabThickness, std::min(zNear, zFar)},
                  {kHalfLength, y, std::max(zNear, zFar)});
        }
    }
    return b.finish();
}

glm::mat4 placed(const glm::vec3& position, float yawDegrees) {
    return glm::rotate(glm::translate(glm::mat4(1.0f), position), glm::radians(yawDegrees),
                       {0.0f, 1.0f, 0.0f});
}

} // namespace

Scene makeAtrium() {
    Scene scene;
    scene.name = "atrium";
    scene.description = "courtyard with two storeys of arcades, drapes and a sun (a stand-in for Sponza)";
    scene.materials = {
        {.name = "stone", .baseColor = {0.62f, 0.58f, 0.52f, 1.0f}, .metallic = 0.0f},
        {.name = "tile light", .baseColor = {0.7f, 0.68f, 0.62f, 1.0f}, .metallic = 0.0f},
        {.name = "tile dark", .baseColor = {0.35f, 0.33f, 0.3f, 1.0f}, .metallic = 0.0f},
        {.name = "plaster", .baseColor = {0.75f, 0.7f, 0.6f, 1.0f}, .metallic = 0.0f},
        {.name = "drape red",
         .baseColor = {0.65f, 0.08f, 0.06f, 1.0f},
         .metallic = 0.0f,
         .doubleSided = true},
        {.name = "drape green",
         .baseColor = {0.1f, 0.5f, 0.15f, 1.0f},
         .metallic = 0.0f,
         .doubleSided = true},
        {.name = "drape blue",
         .baseColor = {0.08f, 0.15f, 0.6f, 1.0f},
         .metallic = 0.0f,
         .doubleSided = true},
        {.name = "bronze", .baseColor = {0.45f, 0.3f, 0.18f, 1.0f}, .metallic = 0.0f, .roughness = 0.6f},
    };
    enum MeshId : uint32_t {
        kStructure,
        kColumn,
        kArch,
        kBalustrade,
        kDrapeRed,
        kDrapeGreen,
        kDrapeBlue,
        kBanner
    };
    scene.meshes = {structureMesh(),
                    columnMesh(),
                    archMesh(),
                    balustradeMesh(),
                    clothMesh("drape red", kRed, 1.6f, 4.2f, 40, 60, 5.0f),
                    clothMesh("drape green", kGreen, 1.6f, 4.2f, 40, 60, 5.0f),
                    clothMesh("drape blue", kBlue, 1.6f, 4.2f, 40, 60, 5.0f),
                    clothMesh("banner", kRed, 4.0f, 8.0f, 48, 96, 6.0f)};
    auto add = [&](uint32_t mesh, const glm::mat4& transform) {
        scene.instances.push_back(
            {.mesh = mesh,
             .transform = transform,
             .name = scene.meshes[mesh].name + " " + std::to_string(scene.instances.size())});
    };
    add(kStructure, glm::mat4(1.0f));
    const std::array<uint32_t, 3> drapes = {kDrapeRed, kDrapeGreen, kDrapeBlue};
    int drapeCount = 0;
    const int bays = int(2.0f * kHalfLength / kBaySpacing);
    for (int storey = 0; storey < kStoreys; ++storey) {
        const float y = kStoreyHeight * float(storey);
        for (const float side : {-1.0f, 1.0f}) {
            // Arcade on z = side * kArcadeZ; its courtyard face looks towards z = 0.
            const float yaw = side > 0 ? 0.0f : 180.0f;
            for (int bay = 0; bay < bays; ++bay) {
                const float x = -kHalfLength + kBaySpacing * (float(bay) + 0.5f);
                add(kArch, placed({x, y + kColumnTop, side * kArcadeZ}, yaw));
                if (bay > 0) {
                    add(kColumn, placed({x - 0.5f * kBaySpacing, y, side * kArcadeZ}, yaw));
                }
                if (storey > 0) {
                    add(kBalustrade, placed({x, y, side * kArcadeZ}, yaw));
                    if (bay % 2 == 1) {
                        const float drapeZ = side * (kArcadeZ - 0.5f * kArchDepth - 0.15f);
                        add(drapes[size_t(drapeCount++) % drapes.size()],
                            placed({x, y + kStoreyHeight - 0.8f, drapeZ}, yaw));
                    }
                }
            }
        }
    }
    add(kBanner, placed({kHalfLength - 0.2f, 11.0f, 0.0f}, 90.0f));
    add(kBanner, placed({-kHalfLength + 0.2f, 11.0f, 0.0f}, -90.0f));

    scene.lights.push_back({.type = LightType::Directional,
                            .name = "sun",
                            .intensity = 10.0f,
                            .direction = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f))});
    scene.camera = {.name = "camera",
                    .position = {-14.0f, 1.7f, -1.0f},
                    .forward = glm::normalize(glm::vec3(22.0f, 2.5f, 2.0f)),
                    .fovY = glm::radians(60.0f),
                    .nearPlane = 0.05f,
                    .farPlane = 100.0f};
    scene.camera.up = glm::normalize(
        glm::cross(glm::cross(scene.camera.forward, glm::vec3(0.0f, 1.0f, 0.0f)), scene.camera.forward));
    scene.cameraFromFile = true;
    scene.sky = {0.35f, 0.5f, 0.8f};
    scene.image = {1280, 720};
    return scene;
}

} // namespace lumina::scene
