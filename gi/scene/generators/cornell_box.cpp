// The Cornell box, from the published measurements
// (https://www.graphics.cornell.edu/online/box/data.html): millimetres, right-handed, y up.
// Vertex lists below are the published ones; each quad's front face looks into the box.
#include "gi/scene/generators/generators.h"
#include "gi/scene/mesh_builder.h"

#include <cmath>

namespace lumina::scene {

namespace {

using V = glm::vec3;

enum CornellMaterial : uint32_t { kWhite, kRed, kGreen, kLight };

// Light quad: 130 mm x 105 mm, radiance (17, 12, 4), emitting downwards only.
constexpr glm::vec3 kLightRadiance{17.0f, 12.0f, 4.0f};
constexpr float kLightArea = 130.0f * 105.0f;
// The point light of the same power: 4 pi I = pi Le A, so I = Le A / 4 (units.h).
constexpr glm::vec3 kPointIntensity = kLightRadiance * (kLightArea / 4.0f);

Mesh quadMesh(const char* name, uint32_t material, V a, V b, V c, V d) {
    MeshBuilder builder(name);
    builder.material(material);
    builder.quad(a, b, c, d);
    return builder.finish();
}

// A block from its top face (counter-clockwise from above) down to y = 0: top and four sides.
Mesh blockMesh(const char* name, const V top[4]) {
    MeshBuilder builder(name);
    builder.material(kWhite);
    builder.quad(top[0], top[1], top[2], top[3]);
    const V centre = (top[0] + top[1] + top[2] + top[3]) * 0.25f;
    for (int i = 0; i < 4; ++i) {
        const V a = top[i], b = top[(i + 1) % 4];
        const V a0(a.x, 0.0f, a.z), b0(b.x, 0.0f, b.z);
        builder.quadFacingAwayFrom(a0, b0, b, a, V(centre.x, 0.5f * centre.y, centre.z));
    }
    return builder.finish();
}

} // namespace

Scene makeCornellBox(bool pointLight) {
    Scene scene;
    scene.name = pointLight ? "cornell_box_point" : "cornell_box";
    scene.description = pointLight ? "Cornell box lit by a point light with the light quad's total power"
                                   : "Cornell box after the published Cornell University data";
    scene.units.metresPerUnit = 0.001;
    scene.materials = {
        {.name = "white", .baseColor = {0.725f, 0.71f, 0.68f, 1.0f}},
        {.name = "red", .baseColor = {0.63f, 0.065f, 0.05f, 1.0f}},
        {.name = "green", .baseColor = {0.14f, 0.45f, 0.091f, 1.0f}},
    };
    if (!pointLight) {
        scene.materials.push_back(
            {.name = "light", .baseColor = {0.0f, 0.0f, 0.0f, 1.0f}, .emission = kLightRadiance});
    }

    scene.meshes.push_back(
        quadMesh("floor", kWhite, V(552.8f, 0, 0), V(0, 0, 0), V(0, 0, 559.2f), V(549.6f, 0, 559.2f)));
    scene.meshes.push_back(quadMesh("ceiling", kWhite, V(556, 548.8f, 0), V(556, 548.8f, 559.2f),
                                    V(0, 548.8f, 559.2f), V(0, 548.8f, 0)));
    scene.meshes.push_back(quadMesh("back wall", kWhite, V(549.6f, 0, 559.2f), V(0, 0, 559.2f),
                                    V(0, 548.8f, 559.2f), V(556, 548.8f, 559.2f)));
    scene.meshes.push_back(
        quadMesh("right wall", kGreen, V(0, 0, 559.2f), V(0, 0, 0), V(0, 548.8f, 0), V(0, 548.8f, 559.2f)));
    scene.meshes.push_back(quadMesh("left wall", kRed, V(552.8f, 0, 0), V(549.6f, 0, 559.2f),
                                    V(556, 548.8f, 559.2f), V(556, 548.8f, 0)));
    const V shortTop[4] = {V(130, 165, 65), V(82, 165, 225), V(240, 165, 272), V(290, 165, 114)};
    const V tallTop[4] = {V(423, 330, 247), V(265, 330, 296), V(314, 330, 456), V(472, 330, 406)};
    scene.meshes.push_back(blockMesh("short block", shortTop));
    scene.meshes.push_back(blockMesh("tall block", tallTop));
    if (!pointLight) {
        scene.meshes.push_back(quadMesh("light", kLight, V(343, 548.7f, 227), V(343, 548.7f, 332),
                                        V(213, 548.7f, 332), V(213, 548.7f, 227)));
    } else {
        scene.lights.push_back({.type = LightType::Point,
                                .name = "light",
                                .color = kPointIntensity / kPointIntensity.x,
                                .intensity = kPointIntensity.x,
                                .position = {278.0f, 538.8f, 279.6f}});
    }
    for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
        scene.instances.push_back({.mesh = i, .transform = glm::mat4(1.0f), .name = scene.meshes[i].name});
    }

    // The published camera: 35 mm focal length, 25 mm film, at (278, 273, -800) looking +z.
    scene.camera = {.name = "camera",
                    .position = {278.0f, 273.0f, -800.0f},
                    .forward = {0.0f, 0.0f, 1.0f},
                    .up = {0.0f, 1.0f, 0.0f},
                    .fovY = float(2.0 * std::atan(12.5 / 35.0)),
                    .nearPlane = 10.0f,
                    .farPlane = 3000.0f};
    scene.cameraFromFile = true;
    scene.image = {512, 512};
    scene.sky = glm::vec3(0.0f);
    return scene;
}

} // namespace lumina::scene
