// Every built-in scene loads by name with exactly the content it should have; the Cornell
// box is checked against the published data.
#include "gi/scene/builtin_scenes.h"
#include "gi/scene/generators/generators.h"
#include "gi/scene/scene_loader.h"

#include <cmath>
#include <gtest/gtest.h>
#include <map>

namespace lumina::scene {
namespace {

struct Counts {
    uint64_t triangles, vertices;
    size_t meshes, instances, materials, lights;
};

void expectCounts(const Scene& scene, const Counts& counts) {
    EXPECT_EQ(scene.triangleCount(), counts.triangles);
    EXPECT_EQ(scene.vertexCount(), counts.vertices);
    EXPECT_EQ(scene.meshes.size(), counts.meshes);
    EXPECT_EQ(scene.instances.size(), counts.instances);
    EXPECT_EQ(scene.materials.size(), counts.materials);
    EXPECT_EQ(scene.lights.size(), counts.lights);
    EXPECT_TRUE(scene.textures.empty());
    EXPECT_TRUE(scene.report.warnings.empty());
}

const Mesh& meshNamed(const Scene& scene, const std::string& name) {
    for (const Mesh& mesh : scene.meshes) {
        if (mesh.name == name) {
            return mesh;
        }
    }
    ADD_FAILURE() << "no mesh " << name;
    return scene.meshes.front();
}

bool hasVertex(const Mesh& mesh, const glm::vec3& p) {
    for (const glm::vec3& q : mesh.positions) {
        if (glm::length(q - p) < 1e-3f) {
            return true;
        }
    }
    return false;
}

glm::vec3 faceNormal(const Mesh& mesh, size_t triangle) {
    const glm::vec3 a = mesh.positions[mesh.indices[triangle * 3]];
    const glm::vec3 b = mesh.positions[mesh.indices[triangle * 3 + 1]];
    const glm::vec3 c = mesh.positions[mesh.indices[triangle * 3 + 2]];
    return glm::normalize(glm::cross(b - a, c - a));
}

// Every edge of the mesh's triangles, by position, is shared by exactly two triangles.
bool isClosed(const Mesh& mesh, const glm::mat4& transform) {
    auto key = [&](uint32_t index) {
        const glm::vec3 p = glm::vec3(transform * glm::vec4(mesh.positions[index], 1.0f)) * 1000.0f;
        return std::tuple(std::lround(p.x), std::lround(p.y), std::lround(p.z));
    };
    std::map<std::pair<std::tuple<long, long, long>, std::tuple<long, long, long>>, int> edges;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) {
            auto a = key(mesh.indices[t + size_t(e)]), b = key(mesh.indices[t + size_t((e + 1) % 3)]);
            ++edges[std::minmax(a, b)];
        }
    }
    for (const auto& [edge, count] : edges) {
        if (count != 2) {
            return false;
        }
    }
    return true;
}

TEST(BuiltinScenes, EveryOneLoadsByName) {
    for (const BuiltinScene& builtin : builtinScenes()) {
        SCOPED_TRACE(std::string(builtin.name));
        const Scene scene =
            loadScene(builtin.name, {.instances = builtin.name == "city" ? std::optional(4u) : std::nullopt});
        EXPECT_EQ(scene.name, builtin.name);
        EXPECT_GT(scene.triangleCount(), 0u);
        EXPECT_TRUE(scene.cameraFromFile);
    }
}

TEST(BuiltinScenes, CornellBoxCounts) {
    expectCounts(loadScene("cornell_box"), {32, 64, 8, 8, 4, 0});
    expectCounts(loadScene("cornell_box_point"), {30, 60, 7, 7, 3, 1});
}

TEST(BuiltinScenes, CornellBoxFollowsThePublishedData) {
    const Scene scene = loadScene("cornell_box");
    EXPECT_DOUBLE_EQ(scene.units.metresPerUnit, 0.001);
    const Mesh& floor = meshNamed(scene, "floor");
    for (const glm::vec3& p : {glm::vec3(552.8f, 0, 0), glm::vec3(0, 0, 0), glm::vec3(0, 0, 559.2f),
                               glm::vec3(549.6f, 0, 559.2f)}) {
        EXPECT_TRUE(hasVertex(floor, p)) << p.x << " " << p.y << " " << p.z;
    }
    EXPECT_TRUE(hasVertex(meshNamed(scene, "ceiling"), {556, 548.8f, 559.2f}));
    EXPECT_TRUE(hasVertex(meshNamed(scene, "back wall"), {556, 548.8f, 559.2f}));
    EXPECT_TRUE(hasVertex(meshNamed(scene, "right wall"), {0, 548.8f, 0}));
    EXPECT_TRUE(hasVertex(meshNamed(scene, "left wall"), {556, 548.8f, 0}));
    EXPECT_TRUE(hasVertex(meshNamed(scene, "short block"), {290, 165, 114}));
    EXPECT_TRUE(hasVertex(meshNamed(scene, "short block"), {290, 0, 114}));
    EXPECT_TRUE(hasVertex(meshNamed(scene, "tall block"), {472, 330, 406}));
    EXPECT_TRUE(hasVertex(meshNamed(scene, "tall block"), {472, 0, 406}));

    // Walls face into the box; the blocks' faces face out of them.
    const glm::vec3 inside(278.0f, 274.0f, 280.0f);
    for (const char* wall : {"floor", "ceiling", "back wall", "right wall", "left wall"}) {
        const Mesh& mesh = meshNamed(scene, wall);
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            EXPECT_GT(glm::dot(faceNormal(mesh, t), inside - mesh.positions[mesh.indices[t * 3]]), 0.0f)
                << wall;
        }
    }
    for (const char* block : {"short block", "tall block"}) {
        const Mesh& mesh = meshNamed(scene, block);
        const glm::vec3 centre = mesh.bounds.centre();
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            EXPECT_GT(glm::dot(faceNormal(mesh, t), mesh.positions[mesh.indices[t * 3]] - centre), 0.0f)
                << block;
        }
    }

    // The light: 130 x 105 mm at y = 548.7, facing down, radiance (17, 12, 4), albedo 0.
    const Mesh& light = meshNamed(scene, "light");
    EXPECT_NEAR(light.bounds.min.y, 548.7f, 1e-3f);
    EXPECT_NEAR(light.bounds.size().x, 130.0f, 1e-3f);
    EXPECT_NEAR(light.bounds.size().z, 105.0f, 1e-3f);
    for (size_t t = 0; t < light.triangleCount(); ++t) {
        EXPECT_NEAR(faceNormal(light, t).y, -1.0f, 1e-6f);
    }
    for (const glm::vec3& n : light.normals) {
        EXPECT_NEAR(n.y, -1.0f, 1e-6f);
    }
    const Material& emitter = scene.materials[light.submeshes[0].material];
    EXPECT_NEAR(emitter.emission.x, 17.0f, 1e-5f);
    EXPECT_NEAR(emitter.emission.y, 12.0f, 1e-5f);
    EXPECT_NEAR(emitter.emission.z, 4.0f, 1e-5f);
    EXPECT_EQ(glm::vec3(emitter.baseColor), glm::vec3(0.0f));
    EXPECT_FALSE(emitter.doubleSided);

    auto albedo = [&](const char* mesh) {
        return glm::vec3(scene.materials[meshNamed(scene, mesh).submeshes[0].material].baseColor);
    };
    EXPECT_EQ(albedo("floor"), glm::vec3(0.725f, 0.71f, 0.68f));
    EXPECT_EQ(albedo("tall block"), glm::vec3(0.725f, 0.71f, 0.68f));
    EXPECT_EQ(albedo("left wall"), glm::vec3(0.63f, 0.065f, 0.05f));
    EXPECT_EQ(albedo("right wall"), glm::vec3(0.14f, 0.45f, 0.091f));

    const Camera& camera = scene.camera;
    EXPECT_NEAR(camera.fovY, 2.0 * std::atan(12.5 / 35.0), 1e-6);
    EXPECT_NEAR(glm::degrees(camera.fovY), 39.3077f, 1e-3f);
    EXPECT_NEAR(glm::length(camera.position - glm::vec3(278.0f, 273.0f, -800.0f)), 0.0f, 1e-3f);
    EXPECT_NEAR(camera.forward.z, 1.0f, 1e-6f);
    EXPECT_NEAR(camera.up.y, 1.0f, 1e-6f);
    // Right-handed, y up, looking along +z: the image's right is -x, so the green wall
    // (x = 0) is on the right and the red one on the left.
    EXPECT_NEAR(camera.right().x, -1.0f, 1e-6f);
    EXPECT_EQ(scene.image.width, scene.image.height);
    EXPECT_EQ(scene.sky, glm::vec3(0.0f));
    EXPECT_TRUE(scene.lights.empty());
    const Bounds bounds = scene.worldBounds();
    EXPECT_NEAR(glm::length(bounds.min), 0.0f, 1e-4f);
    EXPECT_NEAR(glm::length(bounds.max - glm::vec3(556.0f, 548.8f, 559.2f)), 0.0f, 1e-3f);
}

TEST(BuiltinScenes, CornellBoxPointLightHasTheQuadsPower) {
    const Scene scene = loadScene("cornell_box_point");
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& light = scene.lights[0];
    EXPECT_EQ(light.type, LightType::Point);
    EXPECT_NEAR(glm::length(light.position - glm::vec3(278.0f, 538.8f, 279.6f)), 0.0f, 1e-3f);
    const glm::vec3 intensity = light.strength();
    EXPECT_NEAR(intensity.x, 58012.5f, 58012.5f * 1e-5f);
    EXPECT_NEAR(intensity.y, 40950.0f, 40950.0f * 1e-5f);
    EXPECT_NEAR(intensity.z, 13650.0f, 13650.0f * 1e-5f);
    // Total power 4 pi I equals the quad's pi Le A.
    EXPECT_NEAR(4.0 * intensity.x, 17.0 * 130.0 * 105.0, 1.0);
    for (const Mesh& mesh : scene.meshes) {
        EXPECT_NE(mesh.name, "light");
    }
}

TEST(BuiltinScenes, OpenTopBoxIsClosedButForTheRoofOpening) {
    const Scene scene = loadScene("open_top_box");
    expectCounts(scene, {78, 156, 3, 3, 5, 1});
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    EXPECT_LT(scene.lights[0].direction.y, -0.5f);
    // Roof area: the 10 m x 10 m roof less the 2 m x 2 m opening.
    const Mesh& room = meshNamed(scene, "room");
    double roofArea = 0.0;
    for (const Submesh& submesh : room.submeshes) {
        if (scene.materials[submesh.material].name != "roof") {
            continue;
        }
        for (uint32_t i = submesh.firstIndex; i < submesh.firstIndex + submesh.indexCount; i += 3) {
            const glm::vec3 a = room.positions[room.indices[i]], b = room.positions[room.indices[i + 1]],
                            c = room.positions[room.indices[i + 2]];
            roofArea += 0.5 * glm::length(glm::cross(b - a, c - a));
        }
    }
    EXPECT_NEAR(roofArea, 96.0, 1e-4);
    const Bounds bounds = scene.worldBounds();
    EXPECT_TRUE(glm::all(glm::greaterThan(scene.camera.position, bounds.min)));
    EXPECT_TRUE(glm::all(glm::lessThan(scene.camera.position, bounds.max)));
}

// A vertex lying inside another triangle's edge (a T-junction) leaves a seam the rasteriser can
// miss a pixel on, showing what lies behind the wall (docs/gi.md, energy 26.). The rooms' meshes
// are cut so that every shared edge has the same two ends on both sides.
TEST(BuiltinScenes, RoomMeshesHaveNoTJunctions) {
    constexpr float kTolerance = 1e-5f;
    for (const char* name : {"open_top_box", "two_rooms", "sunlit_rooms", "door"}) {
        const Scene scene = loadScene(name);
        for (const Mesh& mesh : scene.meshes) {
            SCOPED_TRACE(std::string(name) + ", mesh " + mesh.name);
            size_t junctions = 0;
            for (size_t i = 0; i < mesh.indices.size(); i += 3) {
                for (size_t e = 0; e < 3; ++e) {
                    const glm::vec3 a = mesh.positions[mesh.indices[i + e]];
                    const glm::vec3 b = mesh.positions[mesh.indices[i + (e + 1) % 3]];
                    const float length = glm::length(b - a);
                    for (const glm::vec3& v : mesh.positions) {
                        const float along = glm::dot(v - a, b - a) / length;
                        const bool inside = along > kTolerance && along < length - kTolerance;
                        junctions += inside && glm::length(v - a - (b - a) * (along / length)) < kTolerance;
                    }
                }
            }
            EXPECT_EQ(junctions, 0u);
        }
    }
}

TEST(BuiltinScenes, FurnacesAreClosedUniformEmitters) {
    for (const float albedo : {0.5f, 0.8f, 0.95f, 0.99f}) {
        char name[32];
        std::snprintf(name, sizeof(name), "furnace_%g", double(albedo));
        SCOPED_TRACE(name);
        const Scene scene = loadScene(name);
        expectCounts(scene, {24, 48, 2, 2, 1, 0});
        const Material& material = scene.materials[0];
        EXPECT_EQ(glm::vec3(material.baseColor), glm::vec3(albedo));
        EXPECT_EQ(material.emission, glm::vec3(1.0f));
        EXPECT_EQ(scene.sky, glm::vec3(0.0f));
        for (const Instance& instance : scene.instances) {
            EXPECT_TRUE(isClosed(scene.meshes[instance.mesh], instance.transform)) << instance.name;
        }
        // The camera is inside the room and outside the block.
        const Bounds room = transformBounds(scene.meshes[0].bounds, scene.instances[0].transform);
        const Bounds block = transformBounds(scene.meshes[1].bounds, scene.instances[1].transform);
        const glm::vec3 eye = scene.camera.position;
        EXPECT_TRUE(glm::all(glm::greaterThan(eye, room.min)) && glm::all(glm::lessThan(eye, room.max)));
        EXPECT_FALSE(glm::all(glm::greaterThan(eye, block.min)) && glm::all(glm::lessThan(eye, block.max)));
        // The room's faces look inwards, at the camera's side.
        const Mesh& shell = scene.meshes[0];
        for (size_t t = 0; t < shell.triangleCount(); ++t) {
            EXPECT_GT(glm::dot(faceNormal(shell, t), -shell.positions[shell.indices[t * 3]]), 0.0f);
        }
    }
}

TEST(BuiltinScenes, AtriumIsSponzaSized) {
    const Scene scene = loadScene("atrium");
    EXPECT_GE(scene.triangleCount(), 100'000u);
    EXPECT_LE(scene.triangleCount(), 300'000u);
    EXPECT_EQ(scene.triangleCount(), 210'168u);
    EXPECT_EQ(scene.meshes.size(), 8u);
    EXPECT_EQ(scene.instances.size(), 175u);
    EXPECT_EQ(scene.materials.size(), 8u);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    EXPECT_EQ(scene.generator, "atrium");
    for (const Mesh& mesh : scene.meshes) {
        for (const glm::vec3& n : mesh.normals) {
            ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << mesh.name;
        }
    }
}

TEST(BuiltinScenes, CityScalesWithItsInstanceCount) {
    const Scene small = loadScene("city", {.instances = 16});
    EXPECT_EQ(small.instances.size(), 17u); // and the ground
    const Scene city = loadScene("city");
    EXPECT_EQ(city.instances.size(), kCityDefaultBuildings + 1);
    EXPECT_GE(city.triangleCount(), 1'500'000u);
    EXPECT_EQ(city.meshes.size(), small.meshes.size());
    EXPECT_GT(city.worldBounds().size().x, small.worldBounds().size().x);
}

} // namespace
} // namespace lumina::scene
