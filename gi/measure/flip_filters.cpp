#include "gi/measure/flip_filters.h"

#include "gi/image/image.h"
#include "gi/measure/flip_color.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lumina::measure::flipmath {

namespace {

constexpr double kPi = std::numbers::pi;

void checkPpd(double pixelsPerDegree) {
    // Above ~1000 ppd the CSF support exceeds any image; below 1 a pixel spans degrees.
    if (!(pixelsPerDegree >= 1.0 && pixelsPerDegree <= 1000.0)) {
        throw image::ImageError("FLIP: pixels per degree " + std::to_string(pixelsPerDegree) +
                                " is outside [1, 1000]");
    }
}

// exp(-pi^2 x^2 / b) at x = (i - r) / ppd, normalised to sum 1; returns the raw sum too.
Kernel1D csfGaussian(int radius, double pixelsPerDegree, double b, double& rawSum) {
    Kernel1D kernel{radius, std::vector<float>(size_t(2 * radius + 1))};
    std::vector<double> raw(kernel.taps.size());
    rawSum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const double x = i / pixelsPerDegree;
        raw[size_t(i + radius)] = std::exp(-kPi * kPi * x * x / b);
        rawSum += raw[size_t(i + radius)];
    }
    for (size_t i = 0; i < raw.size(); ++i) {
        kernel.taps[i] = float(raw[i] / rawSum);
    }
    return kernel;
}

CsfFilter makeCsf(const CsfGaussians& g, int radius, double pixelsPerDegree) {
    // 2D sum of term k: a_k sqrt(pi/b_k) * (1D raw sum)^2; normalise the weights over all terms.
    CsfFilter filter;
    double total = 0.0;
    std::vector<double> weights;
    for (const auto& [a, b] :
         {std::pair{double(g.a1), double(g.b1)}, std::pair{double(g.a2), double(g.b2)}}) {
        if (a == 0.0) {
            continue;
        }
        double rawSum = 0.0;
        Kernel1D kernel = csfGaussian(radius, pixelsPerDegree, b, rawSum);
        const double weight = a * std::sqrt(kPi / b) * rawSum * rawSum;
        weights.push_back(weight);
        total += weight;
        filter.terms.push_back({0.0f, std::move(kernel)});
    }
    for (size_t k = 0; k < filter.terms.size(); ++k) {
        filter.terms[k].weight = float(weights[k] / total);
    }
    return filter;
}

// Scales positive taps to sum 1 and negative taps to sum -1 (1D factor of the 2D rule: the
// other factor is a Gaussian normalised to 1, so 2D lobes sum to +-1 as the paper's code has).
void normaliseLobes(std::vector<double>& taps) {
    double positive = 0.0;
    double negative = 0.0;
    for (double t : taps) {
        (t > 0.0 ? positive : negative) += std::fabs(t);
    }
    for (double& t : taps) {
        if (t > 0.0) {
            t /= positive;
        } else if (t < 0.0) {
            t /= negative;
        }
    }
}

Kernel1D toKernel(int radius, const std::vector<double>& taps) {
    Kernel1D kernel{radius, std::vector<float>(taps.size())};
    std::transform(taps.begin(), taps.end(), kernel.taps.begin(), [](double t) { return float(t); });
    return kernel;
}

} // namespace

int csfRadius(double pixelsPerDegree) {
    checkPpd(pixelsPerDegree);
    const double bMax = std::max({kCsfAchromatic.b1, kCsfAchromatic.b2, kCsfRedGreen.b1, kCsfRedGreen.b2,
                                  kCsfBlueYellow.b1, kCsfBlueYellow.b2});
    return int(std::ceil(3.0 * std::sqrt(bMax / (2.0 * kPi * kPi)) * pixelsPerDegree));
}

std::array<CsfFilter, 3> makeCsfFilters(double pixelsPerDegree) {
    const int radius = csfRadius(pixelsPerDegree);
    return {makeCsf(kCsfAchromatic, radius, pixelsPerDegree), makeCsf(kCsfRedGreen, radius, pixelsPerDegree),
            makeCsf(kCsfBlueYellow, radius, pixelsPerDegree)};
}

FeatureFilters makeFeatureFilters(double pixelsPerDegree) {
    checkPpd(pixelsPerDegree);
    FeatureFilters filters;
    const double sigma = 0.5 * kFeatureWidthDegrees * pixelsPerDegree;
    const int radius = int(std::ceil(3.0 * sigma));
    filters.sigma = float(sigma);
    filters.radius = radius;
    std::vector<double> gauss, edge, point;
    double gaussSum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const double x = i;
        const double g = std::exp(-(x * x) / (2.0 * sigma * sigma));
        gauss.push_back(g);
        gaussSum += g;
        edge.push_back(-x * g);
        point.push_back((x * x / (sigma * sigma) - 1.0) * g);
    }
    for (double& g : gauss) {
        g /= gaussSum;
    }
    normaliseLobes(edge);
    normaliseLobes(point);
    filters.smooth = toKernel(radius, gauss);
    filters.edge = toKernel(radius, edge);
    filters.point = toKernel(radius, point);
    return filters;
}

void correlateSeparable(std::span<const float> in, std::span<float> out, uint32_t width, uint32_t height,
                        const Kernel1D& horizontal, const Kernel1D& vertical, std::vector<float>& scratch) {
    const size_t count = size_t(width) * height;
    scratch.resize(count);
    const int w = int(width);
    const int h = int(height);

    // Horizontal pass: each row padded with its clamped border, then accumulated tap by tap so
    // the inner loop runs along contiguous memory (and vectorises).
    const int rx = horizontal.radius;
    std::vector<float> padded(size_t(w + 2 * rx));
    for (int y = 0; y < h; ++y) {
        const float* row = in.data() + size_t(y) * width;
        for (int x = -rx; x < w + rx; ++x) {
            padded[size_t(x + rx)] = row[std::clamp(x, 0, w - 1)];
        }
        float* dst = scratch.data() + size_t(y) * width;
        std::fill(dst, dst + width, 0.0f);
        for (size_t i = 0; i < horizontal.taps.size(); ++i) {
            const float weight = horizontal.taps[i];
            const float* src = padded.data() + i;
            for (int x = 0; x < w; ++x) {
                dst[x] += weight * src[x];
            }
        }
    }

    // Vertical pass row by row so the inner loop runs along contiguous memory.
    const int ry = vertical.radius;
    for (int y = 0; y < h; ++y) {
        float* dst = out.data() + size_t(y) * width;
        std::fill(dst, dst + width, 0.0f);
        for (int j = -ry; j <= ry; ++j) {
            const float weight = vertical.taps[size_t(j + ry)];
            const float* src = scratch.data() + size_t(std::clamp(y + j, 0, h - 1)) * width;
            for (int x = 0; x < w; ++x) {
                dst[x] += weight * src[x];
            }
        }
    }
}

void applyCsf(std::span<const float> in, std::span<float> out, uint32_t width, uint32_t height,
              const CsfFilter& filter, std::vector<float>& scratch, std::vector<float>& term) {
    std::fill(out.begin(), out.end(), 0.0f);
    term.resize(in.size());
    for (const CsfTerm& t : filter.terms) {
        correlateSeparable(in, term, width, height, t.kernel, t.kernel, scratch);
        for (size_t i = 0; i < out.size(); ++i) {
            out[i] += t.weight * term[i];
        }
    }
}

} // namespace lumina::measure::flipmath
