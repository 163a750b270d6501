// The error of an unbiased Monte Carlo estimate falls as 1/sqrt(spp): the RMS error of a
// furnace image against its exact value Le / (1 - rho), read at 4, 16, 64 and 256 samples per
// pixel of one progressive render, must fit a line of slope -0.5 +- 10% in log-log. A biased
// estimator flattens towards its bias; broken accumulation bends the line.
#include "tests/pathtracer/path_tracer_fixture.h"

#include <cmath>
#include <cstdio>
#include <vector>

namespace lumina::test {
namespace {

using ConvergenceTest = PathTracerTest;

constexpr uint32_t kSize = 24;
constexpr double kExpectedSlope = -0.5;
constexpr double kSlopeTolerance = 0.05; // 10% of the expected slope

double rmsError(const image::Image& image, double exact) {
    double sum = 0.0;
    for (const char* channel : {"R", "G", "B"}) {
        for (float value : image.channel(channel)) {
            sum += (value - exact) * (value - exact);
        }
    }
    return std::sqrt(sum / (3.0 * double(image.pixelCount())));
}

// Least-squares slope of y against x.
double fitSlope(const std::vector<double>& x, const std::vector<double>& y) {
    const double n = double(x.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

TEST_P(ConvergenceTest, ErrorFallsAsOneOverSqrtSpp) {
    const scene::Scene scene = loadBuiltin("furnace_0.5", kSize, kSize);
    const double rho = scene.materials.front().baseColor.r;
    const double exact = scene.materials.front().emission.r / (1.0 - rho);
    const gi::PathTracerScene traced(device(), scene);
    gi::PathTracerSettings settings;
    settings.seed = 7;
    gi::PathTracer tracer(device(), traced, scene, settings);

    std::vector<double> logSpp, logError;
    for (uint32_t spp : {4u, 16u, 64u, 256u}) {
        while (tracer.samples() < spp) {
            addSamples(tracer, std::min(32u, spp - tracer.samples()));
        }
        const double error = rmsError(tracer.readResult().image, exact);
        std::printf("%3u spp: RMS error %.5f\n", spp, error);
        ASSERT_GT(error, 0.0);
        logSpp.push_back(std::log(double(spp)));
        logError.push_back(std::log(error));
    }
    const double slope = fitSlope(logSpp, logError);
    std::printf("fitted slope %.4f (expected %.2f +- %.2f)\n", slope, kExpectedSlope, kSlopeTolerance);
    EXPECT_NEAR(slope, kExpectedSlope, kSlopeTolerance);
}

LUMINA_INSTANTIATE_GPU_TEST(ConvergenceTest);

} // namespace
} // namespace lumina::test
