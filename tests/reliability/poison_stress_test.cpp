// Poison never spreads (issue 24, docs/gi_tests.md#poison). A converged lumen frame of the
// Cornell box (its emissive quad plus a point light, 48x48, low preset) gets NaN, +Inf, a negative
// value and 1e6 times the value into one input for one frame, through the update paths a dynamic
// scene uses (FrameRenderer::setLights, setEmission, moveInstance), and the input is restored the
// frame after. A clean run renders the same frames in lockstep. Every frame:
//   - the finite check (gi/core/finite_check.h) finds no NaN or Inf in anything any pass wrote,
//     the screen-probe radiance history included;
//   - the final HDR image and every history lumen keeps (screen-probe radiance history, the screen
//     temporal irradiance, the surface cache's radiosity and final lighting) are compared with the
//     clean run's by relMSE, and from a stated frame on all are within kRecoveredRelMse.
// Site by site (one test each), value after value in one run: each value starts from the state the
// previous one recovered to. A material texel is no site of its own: material textures are RGBA8
// (scene::Texture::rgba8), which holds no NaN, Inf or negative value, and a float sky is refused at
// load (gi/scene/sky_environment.cpp).
#include "gi/frame/frame_finite_check.h"
#include "gi/measure/metrics.h"
#include "gi/scene/scene_loader.h"
#include "gi/surface_cache/surface_cache.h"
#include "rhi/transfer.h"
#include "shaders/screen_probes/screen_probe_shared.h"
#include "tests/frame/frame_harness.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace lumina::test {
namespace {

constexpr uint32_t kSize = 48;
constexpr uint32_t kSettleFrames = 16; // after the surface cache converged
// Within this relMSE of the clean run an image or history has recovered: the wander between
// converged frames of one run is up to 0.0022 (frame_stability_stress_test.cpp).
constexpr double kRecoveredRelMse = 0.01;
// Frames watched after the poisoned one, and the frame (1 = the poisoned frame) from which every
// watched frame must be recovered. Measured on lavapipe: see kMeasured below and docs/gi_tests.md.
constexpr uint32_t kWatchFrames = 48;
constexpr uint32_t kRecoveryFrames = 32;

enum class Poison { NaN, PlusInf, Negative, Times1e6 };
constexpr Poison kPoisons[] = {Poison::NaN, Poison::PlusInf, Poison::Negative, Poison::Times1e6};

const char* poisonName(Poison p) {
    switch (p) {
    case Poison::NaN:
        return "NaN";
    case Poison::PlusInf:
        return "+Inf";
    case Poison::Negative:
        return "negative";
    case Poison::Times1e6:
        return "1e6x";
    }
    return "?";
}

// The poisoned value of a scalar input `v`.
float poisoned(float v, Poison p) {
    switch (p) {
    case Poison::NaN:
        return std::numeric_limits<float>::quiet_NaN();
    case Poison::PlusInf:
        return std::numeric_limits<float>::infinity();
    case Poison::Negative:
        return -v;
    case Poison::Times1e6:
        return v * 1e6f;
    }
    return v;
}

// The Cornell box with its emissive quad, plus a point light a quarter as strong as
// cornell_box_point's, so that both a light and an emissive material can be poisoned.
scene::Scene poisonScene() {
    scene::Scene scene = scene::loadScene("cornell_box");
    scene::Light light = scene::loadScene("cornell_box_point").lights.at(0);
    light.intensity *= 0.25f;
    light.position = {400.0f, 400.0f, 150.0f};
    scene.lights.push_back(light);
    return scene;
}

uint32_t materialNamed(const scene::Scene& scene, const std::string& name) {
    for (uint32_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].name == name) {
            return i;
        }
    }
    throw std::runtime_error("no material '" + name + "'");
}

uint32_t instanceNamed(const scene::Scene& scene, const std::string& name) {
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        if (scene.instances[i].name == name) {
            return i;
        }
    }
    throw std::runtime_error("no instance '" + name + "'");
}

// One input of the scene: how to poison it through the renderer's update API, and how to restore it.
struct PoisonSite {
    const char* name;
    std::function<void(gi::FrameRenderer&, const scene::Scene&, Poison)> poison;
    std::function<void(gi::FrameRenderer&, const scene::Scene&)> restore;
};

PoisonSite lightIntensity() {
    return {"light intensity",
            [](gi::FrameRenderer& r, const scene::Scene& s, Poison p) {
                std::vector<scene::Light> lights = s.lights;
                lights.back().intensity = poisoned(lights.back().intensity, p);
                r.setLights(lights);
            },
            [](gi::FrameRenderer& r, const scene::Scene& s) { r.setLights(s.lights); }};
}

PoisonSite emissiveStrength() {
    return {"emissive strength",
            [](gi::FrameRenderer& r, const scene::Scene& s, Poison p) {
                const uint32_t m = materialNamed(s, "light");
                const glm::vec3 e = s.materials[m].emission;
                r.setEmission(m, {poisoned(e.x, p), e.y, e.z});
            },
            [](gi::FrameRenderer& r, const scene::Scene& s) {
                const uint32_t m = materialNamed(s, "light");
                r.setEmission(m, s.materials[m].emission);
            }};
}

// Every vertex of the short block, through its instance transform (the only per-frame path to
// vertex positions): a transform whose x scale is NaN, +Inf, -1 (a mirror) or 1e6.
PoisonSite vertexPosition() {
    return {"vertex position",
            [](gi::FrameRenderer& r, const scene::Scene& s, Poison p) {
                const uint32_t i = instanceNamed(s, "short block");
                glm::mat4 t = s.instances[i].transform;
                t[0][0] = poisoned(1.0f, p);
                r.moveInstance(i, t);
            },
            [](gi::FrameRenderer& r, const scene::Scene& s) {
                const uint32_t i = instanceNamed(s, "short block");
                r.moveInstance(i, s.instances[i].transform);
            }};
}

// relMSE over the rgb of float4 entries, skipping those `include` leaves out.
double relMseRgb(const std::vector<glm::vec4>& reference, const std::vector<glm::vec4>& test,
                 const std::function<bool(size_t)>& include = nullptr) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < reference.size() && i < test.size(); ++i) {
        if (include && !include(i)) {
            continue;
        }
        for (int c = 0; c < 3; ++c) {
            const double r = reference[i][c], x = test[i][c];
            sum += (x - r) * (x - r) / (r * r + 0.01);
            ++n;
        }
    }
    return n ? sum / double(n) : 0.0; // NaN in, NaN out: a NaN never compares as recovered
}

// The image and the histories of one frame, as the comparison needs them.
struct FrameState {
    image::Image hdr;
    image::Image screenTemporal;
    std::vector<glm::vec4> probeHistory;
    std::vector<gpu::ScreenProbe> probes;
    std::vector<glm::vec4> radiosity;
    std::vector<glm::vec4> finalLighting;
};

FrameState readState(rhi::IDevice& device, FrameHarness& h) {
    const gi::ScreenProbeGather& gather = h.lumen().screenProbes();
    const gi::ScreenProbeResources& r = gather.resources();
    const surface_cache::SurfaceCache& cache = h.lumen().surfaceCache();
    return {.hdr = h.hdr(),
            .screenTemporal = rgbOnly(h.read(gather.irradiance())),
            .probeHistory = rhi::readBufferAs<glm::vec4>(device, *r.history[gather.current()]),
            .probes = rhi::readBufferAs<gpu::ScreenProbe>(device, *r.probes[gather.current()]),
            .radiosity = cache.readLayer(surface_cache::AtlasLayer::IndirectLight),
            .finalLighting = cache.readLayer(surface_cache::AtlasLayer::FinalLighting)};
}

// The largest relMSE of the poisoned frame's image and histories against the clean one's, and
// which it was.
std::pair<double, const char*> worstError(const FrameState& clean, const FrameState& test) {
    const auto validProbeTexel = [&](size_t i) {
        const size_t probe = i / LUMINA_SP_PROBE_TEXELS;
        return probe < clean.probes.size() && probe < test.probes.size() &&
               clean.probes[probe].info.x == LUMINA_SP_PROBE_VALID &&
               test.probes[probe].info.x == LUMINA_SP_PROBE_VALID;
    };
    const std::pair<double, const char*> errors[] = {
        {measure::relMse(clean.hdr, test.hdr), "final HDR"},
        {measure::relMse(clean.screenTemporal, test.screenTemporal), "screen temporal irradiance"},
        {relMseRgb(clean.probeHistory, test.probeHistory, validProbeTexel), "screen-probe radiance history"},
        {relMseRgb(clean.radiosity, test.radiosity), "surface-cache radiosity (indirect light)"},
        {relMseRgb(clean.finalLighting, test.finalLighting), "surface-cache final lighting"},
    };
    std::pair<double, const char*> worst{0.0, "none"};
    for (const auto& e : errors) {
        if (!(e.first <= worst.first)) { // NaN counts as worst
            worst = e;
        }
    }
    return worst;
}

class PoisonStress : public GpuTest {
protected:
    FrameHarness harness(const scene::Scene& scene, bool checkFinite) {
        return FrameHarness(device(), shaders(), scene,
                            {.width = kSize, .height = kSize, .checkFinite = checkFinite});
    }

    // Poisons `site` with every value in turn, one frame each, and checks the spread.
    void runSite(const PoisonSite& site) {
        const scene::Scene scene = poisonScene();
        FrameHarness clean = harness(scene, false);
        FrameHarness poisonedRun = harness(scene, true);
        gi::watchFloatBuffers(*poisonedRun.finiteCheck(), poisonedRun.renderer());
        const uint32_t settle = clean.renderUntilConverged(kSettleFrames);
        ASSERT_TRUE(clean.converged());
        poisonedRun.render(settle);
        ASSERT_FALSE(poisonedRun.nonFinite()) << poisonedRun.nonFinite()->describe();

        for (Poison p : kPoisons) {
            SCOPED_TRACE(std::string(site.name) + " " + poisonName(p));
            bool refused = false;
            std::string why;
            try {
                site.poison(poisonedRun.renderer(), scene, p);
            } catch (const std::invalid_argument& e) {
                refused = true;
                why = e.what();
            }
            uint32_t recoveredFrom = 1;
            std::pair<double, const char*> firstError{0.0, "none"}, lastBad{0.0, "none"};
            for (uint32_t frame = 1; frame <= kWatchFrames; ++frame) {
                clean.render();
                poisonedRun.render();
                if (frame == 1 && !refused) {
                    site.restore(poisonedRun.renderer(), scene);
                }
                ASSERT_FALSE(poisonedRun.nonFinite())
                    << "frame " << frame << " after the poison: " << poisonedRun.nonFinite()->describe();
                const auto error = worstError(readState(device(), clean), readState(device(), poisonedRun));
                if (frame == 1) {
                    firstError = error;
                }
                if (!(error.first < kRecoveredRelMse)) {
                    recoveredFrom = frame + 1;
                    lastBad = error;
                }
            }
            std::printf(
                "poison %-18s %-8s %s; relMSE in the poisoned frame %.3g (%s); within %.3g of the clean "
                "run from frame %u%s%s\n",
                site.name, poisonName(p), refused ? "refused" : "accepted", firstError.first,
                firstError.second, kRecoveredRelMse, recoveredFrom,
                recoveredFrom > 1 ? std::string(", last over it: " + std::string(lastBad.second)).c_str()
                                  : "",
                refused ? (" (" + why + ")").c_str() : "");
            EXPECT_LE(recoveredFrom, kRecoveryFrames)
                << "last over the bound: " << lastBad.second << " " << lastBad.first;
            if (p != Poison::Times1e6) {
                // A non-finite or negative light, emission or transform is an error at the API.
                EXPECT_TRUE(refused) << "the renderer took a " << poisonName(p) << " " << site.name;
            }
        }
    }
};

TEST_P(PoisonStress, LightIntensityPoisonNeverSpreads) {
    LUMINA_REQUIRE_KERNELS();
    runSite(lightIntensity());
}

TEST_P(PoisonStress, EmissiveStrengthPoisonNeverSpreads) {
    LUMINA_REQUIRE_KERNELS();
    runSite(emissiveStrength());
}

TEST_P(PoisonStress, VertexPositionPoisonNeverSpreads) {
    LUMINA_REQUIRE_KERNELS();
    runSite(vertexPosition());
}

LUMINA_INSTANTIATE_GPU_TEST(PoisonStress);

} // namespace
} // namespace lumina::test
