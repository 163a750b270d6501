// ScreenProbeSettings::validate: the defaults pass, every bad value is refused by name.
#include "gi/screen_probes/screen_probe_settings.h"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

namespace lumina::test {
namespace {

using gi::ScreenProbeSettings;

void expectRefused(const std::function<void(ScreenProbeSettings&)>& change, const std::string& field,
                   const std::string& value) {
    ScreenProbeSettings s;
    change(s);
    try {
        s.validate();
        ADD_FAILURE() << field << " = " << value << " was accepted";
    } catch (const std::invalid_argument& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(field + " = " + value), std::string::npos) << message;
    }
}

TEST(ScreenProbeSettings, DefaultsAreValid) {
    EXPECT_NO_THROW(ScreenProbeSettings{}.validate());
    const ScreenProbeSettings s;
    EXPECT_EQ(s.probeSpacing, 8u);
    EXPECT_EQ(s.raysPerProbe, 64u);
    EXPECT_FLOAT_EQ(s.probeHistoryBlend, 0.1f);
    EXPECT_FALSE(s.nearFieldDistance.has_value()); // a fraction of the global SDF's diagonal
    EXPECT_NO_THROW(ScreenProbeSettings{.nearFieldDistance = 0.0f}.validate());
}

TEST(ScreenProbeSettings, BadValuesAreRefusedByName) {
    expectRefused([](auto& s) { s.probeSpacing = 1; }, "probeSpacing", "1");
    expectRefused([](auto& s) { s.probeSpacing = 65; }, "probeSpacing", "65");
    expectRefused([](auto& s) { s.raysPerProbe = 8; }, "raysPerProbe", "8");
    expectRefused([](auto& s) { s.raysPerProbe = 512; }, "raysPerProbe", "512");
    expectRefused([](auto& s) { s.brdfRayFraction = 1.5f; }, "brdfRayFraction", "1.5");
    expectRefused([](auto& s) { s.lightingPdfFloor = 0.0f; }, "lightingPdfFloor", "0");
    expectRefused([](auto& s) { s.probeHistoryBlend = 0.0f; }, "probeHistoryBlend", "0");
    expectRefused([](auto& s) { s.probeHistoryBlend = std::nanf(""); }, "probeHistoryBlend", "nan");
    expectRefused([](auto& s) { s.outlierClamp = 0.5f; }, "outlierClamp", "0.5");
    expectRefused([](auto& s) { s.outlierClampTexelShare = 0.0f; }, "outlierClampTexelShare", "0");
    expectRefused([](auto& s) { s.outlierClampTexelShare = std::nanf(""); }, "outlierClampTexelShare", "nan");
    expectRefused([](auto& s) { s.coneHalfAngle = -0.1f; }, "coneHalfAngle", "-0.1");
    expectRefused([](auto& s) { s.nearFieldDistance = -1.0f; }, "nearFieldDistance", "-1");
    expectRefused([](auto& s) { s.nearFieldDistance = INFINITY; }, "nearFieldDistance", "inf");
    expectRefused([](auto& s) { s.filterNormalPower = 0.0f; }, "filterNormalPower", "0");
    expectRefused([](auto& s) { s.screenHistoryBlend = 2.0f; }, "screenHistoryBlend", "2");
}

} // namespace
} // namespace lumina::test
