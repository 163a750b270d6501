// DDGI's CPU-side halves (docs/ddgi.md): the ray directions, the irradiance encoding, the
// volumes' placement and atlas layout, and the settings' checks.
#include "gi/ddgi/ddgi_settings.h"
#include "gi/ddgi/ddgi_volumes.h"
#include "shaders/ddgi/ddgi_shared.h"

#include <cmath>
#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>
#include <stdexcept>

namespace lumina::gi {
namespace {

TEST(DdgiRays, FibonacciDirectionsAreUnitAndCoverTheSphereEvenly) {
    for (const uint32_t n : {32u, 112u, 224u}) {
        glm::vec3 mean(0.0f);
        uint32_t upper = 0;
        for (uint32_t k = 0; k < n; ++k) {
            const glm::vec3 d = gpu::ddgiFibonacciDirection(k, n);
            EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
            mean += d / float(n);
            upper += d.y > 0.0f ? 1u : 0u;
        }
        // A balanced set: the mean direction vanishes, any half space holds about half.
        EXPECT_LT(glm::length(mean), 0.02f) << n << " rays";
        EXPECT_NEAR(double(upper) / n, 0.5, 0.1) << n << " rays";
    }
}

TEST(DdgiIrradiance, EncodingSurvivesHalfFloatsFarBeyondTheirRange) {
    // A point light's irradiance in a millimetre scene reaches 1e9 and more; a half tops out at 65504.
    for (const float e : {0.0f, 1e-4f, 0.5f, 3.0f, 7e4f, 1e9f, 1e15f}) {
        const float stored = glm::unpackHalf1x16(glm::packHalf1x16(gpu::ddgiEncodeIrradiance(e)));
        ASSERT_TRUE(std::isfinite(stored)) << e;
        const float back = gpu::ddgiDecodeIrradiance(stored);
        EXPECT_NEAR(back, e, 0.005f * e + 1e-12f) << e; // 5 x 2^-11 relative
    }
}

TEST(DdgiVolumes, AFittedVolumeHasItsProbesAtCellCentres) {
    DdgiSettings s;
    s.probeCounts = {4, 2, 8};
    const scene::Bounds box{{0.0f, 0.0f, 0.0f}, {4.0f, 2.0f, 8.0f}};
    const auto volumes = placeDdgiVolumes(s, box, glm::vec3(100.0f));
    ASSERT_EQ(volumes.size(), 1u);
    EXPECT_EQ(volumes[0].spacing, glm::vec3(1.0f));
    EXPECT_EQ(volumes[0].origin, glm::vec3(0.5f)); // no probe on the box's faces (a room's walls)
    const DdgiAtlasLayout layout = ddgiAtlasLayout(volumes);
    EXPECT_EQ(layout.probes, 64u);
    EXPECT_EQ(layout.tilesAcross, 8u);
    EXPECT_EQ(layout.tileRows, 8u);
}

TEST(DdgiVolumes, AFlatSceneGetsDepth) {
    DdgiSettings s;
    s.probeCounts = {4, 4, 4};
    const auto volumes = placeDdgiVolumes(s, {{0.0f, 0.0f, 0.0f}, {8.0f, 0.0f, 8.0f}}, glm::vec3(0.0f));
    EXPECT_GT(volumes[0].spacing.y, 0.0f);
}

TEST(DdgiVolumes, CascadesFollowTheCameraByWholeCells) {
    DdgiSettings s;
    s.probeCounts = {8, 8, 8};
    s.cascades = 3;
    s.cascadeSpacing = 2.0f;
    const auto a = placeDdgiVolumes(s, {}, glm::vec3(10.0f, 3.0f, -7.0f));
    ASSERT_EQ(a.size(), 3u);
    for (uint32_t c = 0; c < 3; ++c) {
        EXPECT_EQ(a[c].spacing, glm::vec3(2.0f * float(1u << c)));
        const glm::vec3 cells = a[c].origin / a[c].spacing;
        EXPECT_EQ(cells, glm::round(cells)) << "cascade " << c << " is snapped to its cells";
        const glm::vec3 centre = a[c].origin + 0.5f * glm::vec3(a[c].counts - 1u) * a[c].spacing;
        EXPECT_LE(glm::length(centre - glm::vec3(10.0f, 3.0f, -7.0f)), glm::length(a[c].spacing))
            << "cascade " << c << " is centred on the camera";
    }
    // A step smaller than half a cell moves no cascade; a long one moves them all.
    EXPECT_EQ(placeDdgiVolumes(s, {}, glm::vec3(10.4f, 3.0f, -7.0f)), a);
    EXPECT_NE(placeDdgiVolumes(s, {}, glm::vec3(30.0f, 3.0f, -7.0f))[2], a[2]);
    const DdgiAtlasLayout layout = ddgiAtlasLayout(a);
    EXPECT_EQ(layout.firstProbe[2], 2u * 512u);
    EXPECT_EQ(layout.firstRow[1], 8u);
}

TEST(DdgiVolumes, AScrolledCascadeKeepsItsProbesAndResetsTheEnteredPlanes) {
    const DdgiVolumePlacement before{
        .origin = glm::vec3(0.0f), .spacing = glm::vec3(2.0f), .counts = glm::uvec3(8)};
    DdgiVolumePlacement after = before;
    after.origin += glm::vec3(2.0f * 3.0f, 0.0f, -2.0f); // 3 cells along +x, 1 along -z
    const DdgiScroll scroll = scrollDdgiVolume(before, after, glm::uvec3(6, 0, 0));
    EXPECT_FALSE(scroll.reset);
    EXPECT_EQ(scroll.offset, glm::uvec3((6 + 3) % 8, 0, 7));
    EXPECT_EQ(scroll.enteredMin, glm::uvec3(5, 0, 0)); // x: the last 3 planes are new
    EXPECT_EQ(scroll.enteredMax, glm::uvec3(8, 0, 1)); // z: the first plane is new
    // Lattice point c of `after` is the world point of c + move in `before`: the same slot.
    gpu::DdgiVolumeInfo was{}, now{};
    was.counts = now.counts = gpu::uint3(8, 8, 8);
    was.scroll = gpu::uint3(6, 0, 0);
    now.scroll = scroll.offset;
    const glm::uvec3 c(1, 4, 2);
    EXPECT_EQ(gpu::ddgiSlotOfLattice(now, c),
              gpu::ddgiSlotOfLattice(was, c + glm::uvec3(3, 0, 0) - glm::uvec3(0, 0, 1)));
    EXPECT_EQ(gpu::ddgiLatticeOfSlot(now, gpu::ddgiSlotOfLattice(now, c)), c);
    // A jump by the cascade's own size or more keeps nothing.
    after.origin = before.origin + glm::vec3(16.0f, 0.0f, 0.0f);
    EXPECT_TRUE(scrollDdgiVolume(before, after, glm::uvec3(0)).reset);
}

TEST(DdgiSettings, BadValuesAreNamed) {
    DdgiSettings s;
    EXPECT_NO_THROW(s.validate());
    s.raysPerProbe = 16;
    EXPECT_THROW(s.validate(), std::invalid_argument);
    s = {};
    s.hysteresis = 1.0f;
    EXPECT_THROW(s.validate(), std::invalid_argument);
    s = {};
    s.probeCounts = {1, 4, 4};
    EXPECT_THROW(s.validate(), std::invalid_argument);
    s = {};
    s.cascades = 2; // without a spacing
    EXPECT_THROW(s.validate(), std::invalid_argument);
    try {
        s = {};
        s.raysPerProbe = 1000;
        s.validate();
        FAIL() << "1000 rays accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("rays per probe 1000"), std::string::npos) << e.what();
    }
}

TEST(DdgiSettings, SettleUpdatesForgetAllButTwoPercent) {
    const uint32_t n = ddgiSettleUpdates(0.97f);
    EXPECT_LT(std::pow(0.97, double(n)), 0.02);
    EXPECT_GE(std::pow(0.97, double(n - 1)), 0.02);
    EXPECT_EQ(ddgiSettleUpdates(0.0f), 1u);
}

} // namespace
} // namespace lumina::gi
