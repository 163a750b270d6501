#include "gi/ddgi/ddgi_settings.h"

#include "shaders/ddgi/ddgi_shared.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

void require(bool ok, const std::string& what) {
    if (!ok) {
        throw std::invalid_argument("ddgi: " + what);
    }
}

bool fraction(float v) {
    return std::isfinite(v) && v >= 0.0f && v <= 1.0f;
}

void checkCounts(const glm::uvec3& counts, const std::string& what) {
    require(counts.x >= 2 && counts.y >= 2 && counts.z >= 2 &&
                uint64_t(counts.x) * counts.y * counts.z <= 65535,
            what + " " + std::to_string(counts.x) + "x" + std::to_string(counts.y) + "x" +
                std::to_string(counts.z) + " (expected at least 2 per axis, at most 65535 probes)");
}

} // namespace

void DdgiSettings::validate() const {
    require(raysPerProbe > LUMINA_DDGI_FIXED_RAYS && raysPerProbe <= LUMINA_DDGI_MAX_RAYS,
            "rays per probe " + std::to_string(raysPerProbe) + " (expected " +
                std::to_string(LUMINA_DDGI_FIXED_RAYS + 1) + " to " + std::to_string(LUMINA_DDGI_MAX_RAYS) +
                ": the first " + std::to_string(LUMINA_DDGI_FIXED_RAYS) + " are the fixed relocation set)");
    checkCounts(probeCounts, "probe counts");
    require(volumes.size() + cascades <= LUMINA_DDGI_MAX_VOLUMES && (volumes.empty() || cascades == 0),
            "at most " + std::to_string(LUMINA_DDGI_MAX_VOLUMES) + " volumes, either given or cascades");
    for (const DdgiVolumeBox& v : volumes) {
        checkCounts(v.counts, "volume probe counts");
        require(!v.box.empty() && glm::all(glm::lessThan(v.box.min, v.box.max)), "a volume's box is empty");
    }
    require(cascades == 0 || (std::isfinite(cascadeSpacing) && cascadeSpacing > 0.0f),
            "cascade spacing must be > 0 with cascades");
    require(fraction(hysteresis) && hysteresis < 1.0f,
            "hysteresis " + std::to_string(hysteresis) + " (expected 0 <= h < 1)");
    require(fraction(changedHysteresis), "changed hysteresis must lie in [0, 1]");
    require(std::isfinite(largeChangeRatio) && largeChangeRatio >= 1.0f, "large-change ratio must be >= 1");
    require(std::isfinite(distanceSharpness) && distanceSharpness >= 1.0f, "distance sharpness must be >= 1");
    require(std::isfinite(normalBias) && normalBias >= 0.0f && std::isfinite(viewBias) && viewBias >= 0.0f,
            "biases must be finite and not negative");
    require(
        fraction(backfaceFraction) && fraction(minFrontfaceDistance) && maxOffset >= 0.0f && maxOffset < 0.5f,
        "relocation fractions out of range (backface and front-face distance in [0, 1], max offset < 0.5)");
    require(std::isfinite(nearFieldDistance) && nearFieldDistance >= 0.0f,
            "near-field distance must be >= 0");
}

uint32_t ddgiSettleUpdates(float hysteresis) {
    constexpr double kForgotten = 0.02;
    if (!(hysteresis > 0.0f)) {
        return 1;
    }
    return uint32_t(std::ceil(std::log(kForgotten) / std::log(double(std::min(hysteresis, 0.999f)))));
}

float ddgiCascadeSpacing(const scene::Scene& scene, uint32_t cascades, uint32_t probesPerAxis) {
    const double metresPerUnit = scene.units.metresPerUnit > 0.0 ? scene.units.metresPerUnit : 1.0;
    const double coarsestReach = 2.0 * double(giSceneExtent(scene));
    const double cellsAcross =
        double(std::max(probesPerAxis, 2u) - 1) * double(1u << (std::max(cascades, 1u) - 1));
    return float(std::max(kDdgiCascadeSpacingMetres / metresPerUnit, coarsestReach / cellsAcross));
}

DdgiSettings ddgiPreset(std::string_view preset, const scene::Scene& scene) {
    return ddgiPreset(findPreset(preset), scene);
}

DdgiSettings ddgiPreset(const Preset& knobs, const scene::Scene& scene) {
    DdgiSettings s;
    static_cast<GiSceneSettings&>(s) = giScenePreset(knobs, scene);
    s.probeCounts = glm::uvec3(knobs.ddgiProbesPerAxis);
    s.raysPerProbe = knobs.ddgiRaysPerProbe;
    const double metresPerUnit = scene.units.metresPerUnit > 0.0 ? scene.units.metresPerUnit : 1.0;
    if (double(giSceneExtent(scene)) * metresPerUnit > kDdgiCascadeSceneMetres) {
        s.cascades = kDdgiDefaultCascades;
        s.cascadeSpacing = ddgiCascadeSpacing(scene, s.cascades, knobs.ddgiProbesPerAxis);
        s.nearFieldDistance = kDdgiCascadeNearFieldCells * s.cascadeSpacing;
    }
    for (const scene::ProbeVolume& v : scene.probeVolumes) {
        s.volumes.push_back({v.box, v.counts});
    }
    if (!s.volumes.empty()) {
        s.cascades = 0;
    }
    return s;
}

} // namespace lumina::gi
