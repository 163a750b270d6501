#include "gi/screen_probes/screen_probe_settings.h"

#include "shaders/screen_probes/screen_probe_shared.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

[[noreturn]] void bad(const char* name, const std::string& value, const char* expected) {
    throw std::invalid_argument(std::string("screen probes: ") + name + " = " + value + " (expected " +
                                expected + ")");
}

void checkRange(const char* name, float value, float lo, float hi, bool loOpen, const char* expected) {
    const bool below = loOpen ? !(value > lo) : !(value >= lo);
    if (!std::isfinite(value) || below || value > hi) {
        std::ostringstream text; // shortest form: "0.5", not to_string's "0.500000"
        text << value;
        bad(name, text.str(), expected);
    }
}

} // namespace

void ScreenProbeSettings::validate() const {
    static_assert(kMaxRaysPerProbe == LUMINA_SP_MAX_RAYS);
    if (probeSpacing < kMinProbeSpacing || probeSpacing > kMaxProbeSpacing) {
        bad("probeSpacing", std::to_string(probeSpacing),
            (std::to_string(kMinProbeSpacing) + " .. " + std::to_string(kMaxProbeSpacing) + " pixels")
                .c_str());
    }
    if (raysPerProbe < kMinRaysPerProbe || raysPerProbe > kMaxRaysPerProbe) {
        bad("raysPerProbe", std::to_string(raysPerProbe),
            (std::to_string(kMinRaysPerProbe) + " .. " + std::to_string(kMaxRaysPerProbe)).c_str());
    }
    checkRange("adaptiveProbeFraction", adaptiveProbeFraction, 0.0f, 1.0f, false, "0 .. 1 (0: none)");
    checkRange("brdfRayFraction", brdfRayFraction, 0.0f, 1.0f, false, "0 .. 1");
    checkRange("lightingPdfFloor", lightingPdfFloor, 0.0f, 1.0f, true, "0 < floor <= 1");
    checkRange("maxTraceDistance", maxTraceDistance, 0.0f, 1e30f, false,
               ">= 0 (0: the global SDF's diagonal)");
    if (nearFieldDistance) {
        checkRange("nearFieldDistance", *nearFieldDistance, 0.0f, 1e30f, false,
                   ">= 0 (0: no near field; unset: a fraction of the global SDF's diagonal)");
    }
    checkRange("coneHalfAngle", coneHalfAngle, 0.0f, 1.0f, false, "0 .. 1 radian");
    checkRange("originBiasVoxels", originBiasVoxels, 0.0f, 16.0f, false, "0 .. 16 voxels");
    checkRange("probeHistoryBlend", probeHistoryBlend, 0.0f, 1.0f, true, "0 < blend <= 1");
    checkRange("outlierClamp", outlierClamp, 1.0f, 1e30f, false, ">= 1");
    checkRange("outlierClampTexelShare", outlierClampTexelShare, 0.0f, 1e30f, true, "> 0");
    checkRange("historyPlaneTolerance", historyPlaneTolerance, 0.0f, 1.0f, true, "0 < tolerance <= 1");
    checkRange("historyNormalTolerance", historyNormalTolerance, -1.0f, 1.0f, false, "a cosine, -1 .. 1");
    checkRange("filterPlaneScale", filterPlaneScale, 0.0f, 1e30f, true, "> 0");
    checkRange("filterNormalPower", filterNormalPower, 1.0f, 1024.0f, false, "1 .. 1024");
    checkRange("screenHistoryBlend", screenHistoryBlend, 0.0f, 1.0f, true, "0 < blend <= 1");
}

} // namespace lumina::gi
