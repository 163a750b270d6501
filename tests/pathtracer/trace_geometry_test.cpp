// The CPU half of the path tracer's scene: triangles in world space, references that agree
// with GpuScene's index packing, emitters with power-proportional probabilities.
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/pathtracer/trace_geometry.h"
#include "gi/scene/scene_loader.h"
#include "shaders/common/conventions.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <numeric>

namespace lumina::gi {
namespace {

TEST(TraceGeometry, CornellBoxReferencesMatchTheGpuScenePacking) {
    const scene::Scene scene = scene::loadScene("cornell_box");
    const TraceGeometry geometry = buildTraceGeometry(scene);
    ASSERT_EQ(geometry.refs.size(), scene.triangleCount());
    ASSERT_EQ(geometry.triangles.size(), scene.triangleCount());

    std::vector<uint32_t> indices, meshFirstIndex;
    const std::vector<gpu::GpuVertex> vertices = packVertices(scene, indices, meshFirstIndex);
    for (size_t i = 0; i < geometry.refs.size(); ++i) {
        const gpu::PtTriangle& ref = geometry.refs[i];
        const bvh::BuildTriangle& tri = geometry.triangles[i];
        EXPECT_EQ(tri.primId, i);
        const scene::Instance& instance = scene.instances.at(ref.info.x);
        // The packed index buffer names the same corners, in order, that the world triangle has.
        const glm::vec3 corners[3] = {tri.v0, tri.v1, tri.v2};
        for (int c = 0; c < 3; ++c) {
            const glm::vec3 object(vertices.at(indices.at(ref.info.y + c)).positionU);
            const glm::vec3 world(instance.transform * glm::vec4(object, 1.0f));
            EXPECT_EQ(world, corners[c]) << "triangle " << i << " corner " << c;
        }
        EXPECT_EQ(ref.info.z & LUMINA_PT_TRIANGLE_MIRRORED, 0u);
    }
}

TEST(TraceGeometry, CornellBoxLightIsTheOnlyEmitter) {
    const scene::Scene scene = scene::loadScene("cornell_box");
    const TraceGeometry geometry = buildTraceGeometry(scene);
    ASSERT_EQ(geometry.emitters.size(), 2u) << "the light quad: two triangles";
    ASSERT_EQ(geometry.emitterAlias.size(), 2u);
    double pdfSum = 0.0, area = 0.0;
    for (const gpu::PtEmitter& e : geometry.emitters) {
        pdfSum += e.edge1AndPdf.w;
        area += e.v0AndArea.w;
        const gpu::PtTriangle& ref = geometry.refs.at(e.info.x);
        EXPECT_EQ(ref.info.w, &e - geometry.emitters.data());
        // Front face down (-y): the light shines into the box.
        const glm::vec3 n =
            glm::cross(glm::vec3(e.edge1AndPdf), glm::vec3(e.edge2AndSign)) * e.edge2AndSign.w;
        EXPECT_LT(n.y, 0.0f);
    }
    EXPECT_NEAR(pdfSum, 1.0, 1e-6);
    EXPECT_NEAR(area, 130.0 * 105.0, 1.0) << "the published light is 130 x 105 mm";
    // Power: pi Le A (one side), weighted by luminance.
    EXPECT_NEAR(geometry.emittedPower, gpu::luminance({17.0f, 12.0f, 4.0f}) * 130.0 * 105.0 * 3.14159265,
                50.0);
}

TEST(TraceGeometry, EmitterProbabilityFollowsPowerAndSides) {
    scene::Scene scene;
    scene::Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals.assign(3, {0, 0, 1});
    mesh.uvs.assign(3, glm::vec2(0.0f));
    mesh.indices = {0, 1, 2};
    mesh.submeshes = {{0, 3, 0}};
    scene.meshes = {mesh, mesh};
    scene.meshes[1].submeshes[0].material = 1;
    scene::Material a, b;
    a.emission = glm::vec3(1.0f);
    b.emission = glm::vec3(1.0f);
    b.doubleSided = true; // emits from both faces: twice the power
    scene.materials = {a, b};
    // The second triangle is twice as large in each direction (4x the area) and mirrored.
    scene.instances = {{0, glm::mat4(1.0f), "a"},
                       {1, glm::scale(glm::mat4(1.0f), glm::vec3(-2.0f, 2.0f, 1.0f)), "b"}};
    const TraceGeometry geometry = buildTraceGeometry(scene);
    ASSERT_EQ(geometry.emitters.size(), 2u);
    EXPECT_NEAR(geometry.emitters[0].edge1AndPdf.w, 1.0 / 9.0, 1e-6);
    EXPECT_NEAR(geometry.emitters[1].edge1AndPdf.w, 8.0 / 9.0, 1e-6);
    EXPECT_EQ(geometry.refs[1].info.z & LUMINA_PT_TRIANGLE_MIRRORED, LUMINA_PT_TRIANGLE_MIRRORED);
    EXPECT_EQ(geometry.refs[1].info.z >> 8u, 1u);
    EXPECT_EQ(geometry.emitters[1].edge2AndSign.w, -1.0f);
    // The mirrored triangle's front still faces +z, where its transformed normal points.
    const glm::vec3 n = glm::cross(glm::vec3(geometry.emitters[1].edge1AndPdf),
                                   glm::vec3(geometry.emitters[1].edge2AndSign)) *
                        geometry.emitters[1].edge2AndSign.w;
    EXPECT_GT(n.z, 0.0f);
}

TEST(TraceGeometry, NoEmittersWithoutEmission) {
    const scene::Scene scene = scene::loadScene("cornell_box_point");
    const TraceGeometry geometry = buildTraceGeometry(scene);
    EXPECT_TRUE(geometry.emitters.empty());
    EXPECT_TRUE(geometry.emitterAlias.empty());
    for (const gpu::PtTriangle& ref : geometry.refs) {
        EXPECT_EQ(ref.info.w, LUMINA_PT_NOT_EMISSIVE);
    }
}

} // namespace
} // namespace lumina::gi
