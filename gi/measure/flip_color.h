#pragma once
// The colour arithmetic of LDR-FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom,
// Fairchild, "FLIP: A Difference Evaluator for Alternating Images", HPG 2020), exposed for
// tests: colour spaces, the Hunt adjustment, HyAB, the error redistribution and the feature
// difference. Constants are the paper's; docs/measurement.md lists them with their sources.
#include <cmath>

namespace lumina::measure::flipmath {

struct Color3 {
    float x = 0.0f;
    float y = 0.0f;
    float z = 0.0f;
};

// Colour pipeline: exponent on HyAB, and the large-difference compression that maps
// [0, p_c * c_max) to [0, p_t) and [p_c * c_max, c_max] to [p_t, 1].
inline constexpr float kQc = 0.7f;
inline constexpr float kPc = 0.4f;
inline constexpr float kPt = 0.95f;
// Feature pipeline: detector width w in degrees (sigma = 0.5 * w * ppd pixels) and exponent.
inline constexpr float kFeatureWidthDegrees = 0.082f;
inline constexpr float kQf = 0.5f;

// Contrast sensitivity as sums of Gaussians in frequency, A(f) = a1 e^(-b1 f^2) + a2 e^(-b2 f^2),
// whose spatial form is S(x) = a1 sqrt(pi/b1) e^(-pi^2 x^2 / b1) + (same for a2, b2), x in degrees.
struct CsfGaussians {
    float a1, b1, a2, b2;
};
inline constexpr CsfGaussians kCsfAchromatic = {1.0f, 0.0047f, 0.0f, 1.0e-5f};
inline constexpr CsfGaussians kCsfRedGreen = {1.0f, 0.0053f, 0.0f, 1.0e-5f};
inline constexpr CsfGaussians kCsfBlueYellow = {34.1f, 0.04f, 13.5f, 0.025f};

// Linear sRGB (Rec.709 primaries, D65) to CIE XYZ, IEC 61966-2-1.
inline Color3 linearRgbToXyz(Color3 c) {
    return {0.4123908f * c.x + 0.3575843f * c.y + 0.1804808f * c.z,
            0.2126390f * c.x + 0.7151687f * c.y + 0.0721923f * c.z,
            0.0193308f * c.x + 0.1191948f * c.y + 0.9505322f * c.z};
}

inline Color3 xyzToLinearRgb(Color3 c) {
    return {3.2409699f * c.x - 1.5373832f * c.y - 0.4986108f * c.z,
            -0.9692436f * c.x + 1.8759675f * c.y + 0.0415551f * c.z,
            0.0556301f * c.x - 0.2039770f * c.y + 1.0569715f * c.z};
}

// Reference white: XYZ of linear RGB (1,1,1) under the matrix above, so white is exactly
// neutral (FLIP's own code uses a D65 white that differs in the fifth digit).
inline constexpr Color3 kWhite = {0.4123908f + 0.3575843f + 0.1804808f, 1.0f,
                                  0.0193308f + 0.1191948f + 0.9505322f};

// YyCxCz, the linearised CIELab of Flohr et al. used by FLIP for filtering.
inline Color3 xyzToYcxcz(Color3 c) {
    const float xr = c.x / kWhite.x;
    const float yr = c.y / kWhite.y;
    const float zr = c.z / kWhite.z;
    return {116.0f * yr - 16.0f, 500.0f * (xr - yr), 200.0f * (yr - zr)};
}

inline Color3 ycxczToXyz(Color3 c) {
    const float yr = (c.x + 16.0f) / 116.0f;
    const float xr = yr + c.y / 500.0f;
    const float zr = yr - c.z / 200.0f;
    return {xr * kWhite.x, yr * kWhite.y, zr * kWhite.z};
}

// CIE 1976 L*a*b*.
inline float labF(float t) {
    constexpr float delta = 6.0f / 29.0f;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

inline Color3 xyzToLab(Color3 c) {
    const float fx = labF(c.x / kWhite.x);
    const float fy = labF(c.y / kWhite.y);
    const float fz = labF(c.z / kWhite.z);
    return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// Hunt effect: chroma is less visible at low luminance, so a* and b* are scaled by L*/100.
inline Color3 huntAdjust(Color3 lab) {
    return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z};
}

// HyAB (Abasi et al. 2020): city-block in lightness, Euclidean in chroma.
inline float hyab(Color3 a, Color3 b) {
    const float da = a.y - b.y;
    const float db = a.z - b.z;
    return std::fabs(a.x - b.x) + std::sqrt(da * da + db * db);
}

// c_max: HyAB^q_c between Hunt-adjusted pure green and pure blue, the largest in the RGB cube.
inline float maxColorDistance() {
    const Color3 green = huntAdjust(xyzToLab(linearRgbToXyz({0.0f, 1.0f, 0.0f})));
    const Color3 blue = huntAdjust(xyzToLab(linearRgbToXyz({0.0f, 0.0f, 1.0f})));
    return std::pow(hyab(green, blue), kQc);
}

// Delta E_c in [0,1] from a HyAB distance of Hunt-adjusted L*a*b* colours.
inline float colorError(float hyabDistance, float cmax) {
    const float e = std::pow(hyabDistance, kQc);
    const float pcCmax = kPc * cmax;
    const float out = e < pcCmax ? e * (kPt / pcCmax) : kPt + (e - pcCmax) / (cmax - pcCmax) * (1.0f - kPt);
    return out < 1.0f ? out : 1.0f; // c_max is the cube's largest distance: a guard, not a change
}

// Delta E_f in [0,1] from the edge and point detector magnitudes of both images.
inline float featureError(float edgeReference, float edgeTest, float pointReference, float pointTest) {
    // Each magnitude is at most sqrt(2) (detector lobes sum to +-1 per axis); the clamp only
    // absorbs rounding so that 1 - Delta E_f never goes negative.
    const float difference =
        std::fmax(std::fabs(edgeReference - edgeTest), std::fabs(pointReference - pointTest)) /
        std::sqrt(2.0f);
    return std::pow(std::fmin(difference, 1.0f), kQf);
}

// Delta E = Delta E_c ^ (1 - Delta E_f).
inline float combineErrors(float colorErr, float featureErr) {
    return std::pow(colorErr, 1.0f - featureErr);
}

} // namespace lumina::measure::flipmath
