// shaders/common/lights_shared.h evaluated in C++ (the code the kernels run), against the
// conventions of gi/scene/units.h and KHR_lights_punctual written out here.
#include "gi/pathtracer/light_packing.h"

#include <cmath>
#include <gtest/gtest.h>

namespace lumina::gi {
namespace {

TEST(Lights, PointLightIsInverseSquare) {
    scene::Light light;
    light.type = scene::LightType::Point;
    light.position = {1.0f, 2.0f, 3.0f};
    light.color = {1.0f, 0.5f, 0.25f};
    light.intensity = 8.0f;
    const gpu::GpuLight gpuLight = packLight(light);
    const glm::vec3 p(1.0f, 2.0f, -1.0f); // 4 units away along -z
    const gpu::LightSample s = gpu::evaluateLight(gpuLight, p);
    EXPECT_NEAR(s.distance, 4.0f, 1e-6f);
    EXPECT_NEAR(glm::length(s.direction - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(s.irradiance.r, 8.0f / 16.0f, 1e-6f);
    EXPECT_NEAR(s.irradiance.g, 4.0f / 16.0f, 1e-6f);
    EXPECT_NEAR(s.irradiance.b, 2.0f / 16.0f, 1e-6f);
}

TEST(Lights, RangeWindowFollowsKhrLightsPunctual) {
    scene::Light light;
    light.type = scene::LightType::Point;
    light.range = 10.0f;
    const gpu::GpuLight gpuLight = packLight(light);
    for (float d : {1.0f, 5.0f, 9.0f, 9.99f, 10.0f, 12.0f}) {
        const gpu::LightSample s = gpu::evaluateLight(gpuLight, glm::vec3(d, 0.0f, 0.0f));
        const float window = std::clamp(1.0f - std::pow(d / 10.0f, 4.0f), 0.0f, 1.0f);
        EXPECT_NEAR(s.irradiance.r, window / (d * d), 1e-6f) << "d " << d;
    }
    light.range = 0.0f; // unlimited
    EXPECT_NEAR(gpu::evaluateLight(packLight(light), glm::vec3(100.0f, 0, 0)).irradiance.r, 1e-4f, 1e-9f);
}

TEST(Lights, SpotConeIsSquaredLinearInCos) {
    scene::Light light;
    light.type = scene::LightType::Spot;
    light.direction = {0.0f, -1.0f, 0.0f};
    light.position = {0.0f, 1.0f, 0.0f};
    light.innerConeAngle = glm::radians(10.0f);
    light.outerConeAngle = glm::radians(30.0f);
    const gpu::GpuLight gpuLight = packLight(light);
    const float cosInner = std::cos(light.innerConeAngle), cosOuter = std::cos(light.outerConeAngle);
    for (float degrees : {0.0f, 5.0f, 10.0f, 20.0f, 29.0f, 30.0f, 45.0f, 90.0f, 135.0f}) {
        const float a = glm::radians(degrees);
        const glm::vec3 p = light.position + glm::vec3(std::sin(a), -std::cos(a), 0.0f) * 2.0f;
        const gpu::LightSample s = gpu::evaluateLight(gpuLight, p);
        const float t = std::clamp((std::cos(a) - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
        EXPECT_NEAR(s.irradiance.r, t * t / 4.0f, 1e-5f) << degrees << " degrees";
    }
}

TEST(Lights, DirectionalLightIsIrradianceFromOppositeItsTravel) {
    scene::Light light;
    light.type = scene::LightType::Directional;
    light.direction = {0.0f, -2.0f, 0.0f}; // packLight normalises
    light.intensity = 3.0f;
    const gpu::LightSample s = gpu::evaluateLight(packLight(light), glm::vec3(5.0f, 7.0f, 9.0f));
    EXPECT_NEAR(glm::length(s.direction - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(s.distance, LUMINA_LIGHT_INFINITE_DISTANCE);
    EXPECT_EQ(s.irradiance, glm::vec3(3.0f));
}

TEST(Lights, EmissionLeavesTheFrontFaceUnlessDoubleSided) {
    const glm::vec3 le(1.0f, 2.0f, 3.0f);
    EXPECT_EQ(gpu::emittedRadiance(le, 0u, 0.5f), le);
    EXPECT_EQ(gpu::emittedRadiance(le, 0u, -0.5f), glm::vec3(0.0f));
    EXPECT_EQ(gpu::emittedRadiance(le, LUMINA_MATERIAL_DOUBLE_SIDED, -0.5f), le);
}

} // namespace
} // namespace lumina::gi
