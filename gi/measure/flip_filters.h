#pragma once
// The spatial filters of LDR-FLIP, all separable, applied as correlations with clamp-to-edge
// borders (the paper's code "replicates" borders too).
//
// CSF filters (colour pipeline): per opponent channel, the 2D kernel
//   K(x, y) = sum_k a_k sqrt(pi / b_k) exp(-pi^2 (x^2 + y^2) / b_k),  x, y in degrees = pixels / ppd,
// normalised to sum 1 over a (2r+1)^2 support, r = ceil(3 sqrt(b_max / (2 pi^2)) ppd), b_max = 0.04.
// Each Gaussian term is separable; the blue-yellow channel's two terms are filtered apart and summed.
//
// Feature detectors: sigma = 0.5 * w * ppd pixels (w = 0.082 deg), r = ceil(3 sigma); edge
// -x G(x, y), point (x^2 / sigma^2 - 1) G(x, y) (and the same in y), each scaled so its positive
// weights sum to 1 and its negative weights to -1. Both factor into a 1D derivative kernel times
// a 1D Gaussian normalised to sum 1.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace lumina::measure::flipmath {

struct Kernel1D {
    int radius = 0;
    std::vector<float> taps; // 2 * radius + 1, tap i weighs the sample at offset i - radius
};

// One separable term of a CSF filter: weight * (kernel x kernel).
struct CsfTerm {
    float weight = 0.0f;
    Kernel1D kernel; // sums to 1
};

struct CsfFilter {
    std::vector<CsfTerm> terms; // weights sum to 1
};

// Achromatic, red-green, blue-yellow.
std::array<CsfFilter, 3> makeCsfFilters(double pixelsPerDegree);
int csfRadius(double pixelsPerDegree);

struct FeatureFilters {
    float sigma = 0.0f; // pixels
    int radius = 0;
    Kernel1D smooth; // Gaussian, sums to 1
    Kernel1D edge;   // -x G(x), positive part sums to 1, negative part to -1
    Kernel1D point;  // (x^2/sigma^2 - 1) G(x), same normalisation
};

FeatureFilters makeFeatureFilters(double pixelsPerDegree);

// out(x, y) = sum_i sum_j horizontal[i] vertical[j] in(clamp(x + i - r), clamp(y + j - r)).
// `scratch` is resized as needed and may be reused across calls.
void correlateSeparable(std::span<const float> in, std::span<float> out, uint32_t width, uint32_t height,
                        const Kernel1D& horizontal, const Kernel1D& vertical, std::vector<float>& scratch);

// Applies a CSF filter (a sum of separable terms) to one plane.
void applyCsf(std::span<const float> in, std::span<float> out, uint32_t width, uint32_t height,
              const CsfFilter& filter, std::vector<float>& scratch, std::vector<float>& term);

} // namespace lumina::measure::flipmath
