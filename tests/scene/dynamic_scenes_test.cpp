// The built-in dynamic scenes load with their animation and do what their scene files say:
// the Cornell box's short block slides and comes back, the atrium's sun crosses the sky with a
// unit direction, the door turns about its hinge.
#include "gi/scene/animation_summary.h"
#include "gi/scene/generators/generators.h"
#include "gi/scene/scene_loader.h"

#include <gtest/gtest.h>

namespace lumina::scene {
namespace {

uint32_t instanceNamed(const Scene& scene, const std::string& name) {
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        if (scene.instances[i].name == name) {
            return i;
        }
    }
    ADD_FAILURE() << "no instance " << name;
    return 0;
}

uint64_t loopFrames(const Scene& scene) {
    return uint64_t(std::llround(scene.animation.length() * scene.framesPerSecond));
}

Bounds instanceBounds(const Scene& scene, uint32_t instance) {
    return transformBounds(scene.meshes[scene.instances[instance].mesh].bounds,
                           scene.instances[instance].transform);
}

TEST(DynamicScenes, CornellBoxBlockSlidesAcrossTheFloorAndBack) {
    Scene scene = loadScene("cornell_box_moving");
    EXPECT_EQ(loopFrames(scene), 360u);
    const uint32_t block = instanceNamed(scene, "short block");
    EXPECT_EQ(scene.animation.animatedInstances(), std::vector<uint32_t>{block});
    const Bounds rest = instanceBounds(scene, block);
    float farthest = 0.0f;
    for (uint64_t frame = 0; frame <= 360; frame += 10) {
        animateScene(scene, frame);
        const Bounds moved = instanceBounds(scene, block);
        EXPECT_NEAR(moved.min.y, 0.0f, 1e-3f) << "stays on the floor at frame " << frame;
        EXPECT_GT(moved.min.x, 0.0f);
        EXPECT_LT(moved.max.x, 549.6f) << "inside the red wall at frame " << frame;
        EXPECT_GT(moved.min.z, 0.0f);
        farthest = std::max(farthest, glm::length(moved.centre() - rest.centre()));
    }
    EXPECT_NEAR(farthest, std::sqrt(230.0f * 230.0f + 55.0f * 55.0f), 1e-2f);
    animateScene(scene, 180);
    EXPECT_NEAR(instanceBounds(scene, block).centre().x - rest.centre().x, 230.0f, 1e-3f);
    animateScene(scene, 360);
    EXPECT_NEAR(glm::length(instanceBounds(scene, block).centre() - rest.centre()), 0.0f, 1e-3f);
    // Nothing else moves.
    const Scene still = loadScene("cornell_box");
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        if (i != block) {
            EXPECT_EQ(scene.instances[i].transform, still.instances[i].transform) << scene.instances[i].name;
        }
    }
}

TEST(DynamicScenes, AtriumSunSweepsAcrossTheSky) {
    Scene scene = loadScene("atrium_day");
    EXPECT_EQ(loopFrames(scene), 1200u);
    ASSERT_EQ(scene.lights.size(), 1u);
    const glm::vec3 morning = scene.lights[0].direction;
    glm::vec3 previous = morning;
    float highest = 0.0f;
    for (uint64_t frame = 0; frame < 1200; frame += 7) {
        animateScene(scene, frame);
        const Light& sun = scene.lights[0];
        ASSERT_NEAR(glm::length(sun.direction), 1.0f, 1e-5f) << frame;
        EXPECT_LT(sun.direction.y, 0.0f) << "the sun stays above the horizon at frame " << frame;
        // At most 0.2 degrees a frame: 7 frames turn it less than 0.03 rad.
        EXPECT_LT(glm::length(sun.direction - previous), 0.03f) << "a smooth path at frame " << frame;
        EXPECT_GT(sun.intensity, 0.0f);
        previous = sun.direction;
        highest = std::max(highest, -sun.direction.y);
    }
    EXPECT_LE(highest, std::sin(glm::radians(60.0f)) + 1e-5f);
    animateScene(scene, 1199);
    // Rises towards -x (travelling +x), sets towards +x (travelling -x).
    EXPECT_GT(morning.x, 0.9f);
    EXPECT_LT(scene.lights[0].direction.x, -0.9f);
    animateScene(scene, 600); // noon
    EXPECT_NEAR(scene.lights[0].intensity, 10.0f, 1e-5f);
    EXPECT_NEAR(-scene.lights[0].direction.y, std::sin(glm::radians(60.0f)), 1e-5f);
}

TEST(DynamicScenes, DoorTurnsAboutItsHinge) {
    Scene scene = loadScene("door");
    EXPECT_EQ(loopFrames(scene), 480u);
    EXPECT_LE(scene.triangleCount(), 200u);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_LT(scene.lights[0].position.x, 0.0f) << "the lamp is in the west room";
    EXPECT_GT(scene.camera.position.x, 0.0f) << "the camera is in the east room";
    const uint32_t door = instanceNamed(scene, "door");
    EXPECT_EQ(scene.animation.animatedInstances(), std::vector<uint32_t>{door});
    const Mesh& mesh = scene.meshes[scene.instances[door].mesh];
    const glm::vec3 hinge = doorHinge();
    // The corners on the hinge axis stay; the free edge swings 90 degrees into the east room.
    const glm::vec3 hingeTop(hinge.x, mesh.bounds.max.y, hinge.z);
    const glm::vec3 freeEdge(hinge.x, 1.0f, mesh.bounds.max.z);
    const float width = mesh.bounds.max.z - hinge.z;
    const glm::mat4 closed = scene.instances[door].transform;
    for (uint64_t frame = 0; frame <= 480; frame += 20) {
        animateScene(scene, frame);
        const glm::mat4& m = scene.instances[door].transform;
        const glm::vec3 top = glm::vec3(m * glm::vec4(hingeTop, 1.0f));
        EXPECT_NEAR(glm::length(top - hingeTop), 0.0f, 1e-4f) << "hinge at frame " << frame;
        const glm::vec3 free = glm::vec3(m * glm::vec4(freeEdge, 1.0f));
        EXPECT_NEAR(glm::length(free - hinge - glm::vec3(0.0f, 1.0f, 0.0f)), width, 1e-4f);
        EXPECT_GE(free.x, hinge.x - 1e-4f) << "opens into the east room at frame " << frame;
    }
    animateScene(scene, 240); // wide open
    const glm::vec3 open = glm::vec3(scene.instances[door].transform * glm::vec4(freeEdge, 1.0f));
    EXPECT_NEAR(open.x, hinge.x + width, 1e-4f);
    EXPECT_NEAR(open.z, hinge.z, 1e-4f);
    animateScene(scene, 480);
    EXPECT_EQ(scene.instances[door].transform, closed);
}

} // namespace
} // namespace lumina::scene

namespace lumina::scene {
namespace {

// What the bench relies on: a frame replays exactly, whatever frames were evaluated before.
TEST(DynamicScenes, FramesReplayExactlyInAnyOrder) {
    for (const char* name : {"cornell_box_moving", "atrium_day", "door"}) {
        SCOPED_TRACE(name);
        Scene fresh = loadScene(name);
        Scene replayed = fresh;
        animateScene(fresh, 333);
        for (const uint64_t frame : {332u, 5000u, 1u, 334u, 0u}) {
            animateScene(replayed, frame);
        }
        animateScene(replayed, 333);
        for (size_t i = 0; i < fresh.instances.size(); ++i) {
            ASSERT_EQ(fresh.instances[i].transform, replayed.instances[i].transform);
        }
        for (size_t i = 0; i < fresh.lights.size(); ++i) {
            EXPECT_EQ(fresh.lights[i].direction, replayed.lights[i].direction);
            EXPECT_EQ(fresh.lights[i].color, replayed.lights[i].color);
            EXPECT_EQ(fresh.lights[i].intensity, replayed.lights[i].intensity);
        }
    }
}

TEST(DynamicScenes, SummariesNameTracksAndLoopLength) {
    const std::vector<std::string> moving = animationSummary(loadScene("cornell_box_moving"));
    ASSERT_EQ(moving.size(), 2u);
    EXPECT_EQ(moving[0],
              "1 track on 1 instance, 0 lights, 0 materials; loops every 6 s (360 frames at 60 per second)");
    EXPECT_EQ(moving[1], "object 'short block': translation (5 keys, linear)");
    const std::vector<std::string> day = animationSummary(loadScene("atrium_day"));
    ASSERT_EQ(day.size(), 2u);
    EXPECT_EQ(day[1],
              "light 'sun': sun path (5 keys, linear), colour (5 keys, linear), intensity (5 keys, linear)");
    EXPECT_EQ(animationSummary(loadScene("cornell_box")), std::vector<std::string>{"none"});
}

} // namespace
} // namespace lumina::scene
