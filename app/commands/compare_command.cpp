// `lumina compare REF.exr TEST.exr`: how far a rendered image is from a reference, on linear
// radiance (relMSE, RMSE, worst pixel) and as displayed (PSNR, LDR-FLIP), with NaN/Inf counts.
#include "app/command.h"
#include "app/commands/number_text.h"
#include "gi/image/exr.h"
#include "gi/image/png.h"
#include "gi/measure/compare.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace lumina::app {

namespace {

std::string counts(const measure::NonFiniteCounts& c) {
    return std::to_string(c.nanPixels) + " NaN + " + std::to_string(c.infPixels) + " Inf pixels";
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file << text;
    file.close();
    if (!file) {
        throw image::ImageError(path + ": cannot write");
    }
}

// Mean R, G, B over the finite pixels: whether the test image has the reference's energy.
std::string meanRgb(const image::Image& image) {
    double sum[3] = {0.0, 0.0, 0.0};
    uint64_t count = 0;
    const auto r = image.channel("R"), g = image.channel("G"), b = image.channel("B");
    for (size_t i = 0; i < r.size(); ++i) {
        if (std::isfinite(r[i]) && std::isfinite(g[i]) && std::isfinite(b[i])) {
            sum[0] += r[i];
            sum[1] += g[i];
            sum[2] += b[i];
            ++count;
        }
    }
    const double n = double(count == 0 ? 1 : count);
    return "(" + numberText(sum[0] / n, 6) + ", " + numberText(sum[1] / n, 6) + ", " +
           numberText(sum[2] / n, 6) + ")";
}

void printReport(const std::string& refPath, const std::string& testPath, const image::Image& reference,
                 const image::Image& test, const measure::CompareResult& result,
                 const measure::CompareOptions& options) {
    std::ostringstream out;
    out << "compare: " << refPath << " (reference) vs " << testPath << ", " << result.width << "x"
        << result.height << ", " << result.linear.pixels << " pixels compared\n";
    out << "  relMSE     " << numberText(result.linear.relMse, 6)
        << "   linear radiance, mean (x-r)^2/(r^2+0.01)\n";
    out << "  RMSE       " << numberText(result.linear.rmse, 6) << "   linear radiance\n";
    out << "  mean       reference " << meanRgb(reference) << ", test " << meanRgb(test)
        << "   linear R, G, B over finite pixels\n";
    out << "  PSNR       "
        << (std::isfinite(result.psnr) ? numberText(result.psnr, 5) + " dB" : std::string("inf dB"))
        << "   tonemapped sRGB, peak 1\n";
    out << "  max error  relMSE " << numberText(result.linear.maxRelMse.value, 6) << " at ("
        << result.linear.maxRelMse.x << ", " << result.linear.maxRelMse.y << ")\n";
    out << "  FLIP       mean " << numberText(result.flip.mean, 6) << ", max "
        << numberText(result.flip.max, 6) << " at (" << result.flip.maxX << ", " << result.flip.maxY
        << ")   LDR-FLIP, " << numberText(options.flip.pixelsPerDegree, 4) << " ppd, exposure "
        << numberText(options.display.exposureEv, 4) << " EV\n";
    out << "  NaN/Inf    reference " << counts(result.reference) << ", test " << counts(result.test) << '\n';
    std::cout << out.str();
}

// The reference of `--exact V`: every pixel of TEST's size at radiance V in R, G and B.
image::Image constantImage(const image::Image& like, float value) {
    image::Image image = image::Image::rgb(like.width(), like.height());
    for (const char* c : {"R", "G", "B"}) {
        std::ranges::fill(image.channel(c), value);
    }
    return image;
}

int runCompare(const ParsedArgs& args) {
    // A furnace's answer is known exactly: against it, a path-traced reference's own noise (which
    // at 1,024 spp in furnace_0.99 is most of the relMSE) does not hide the test image's error.
    const bool exact = args.has("exact");
    const size_t images = exact ? 1 : 2;
    if (args.positional.size() != images) {
        throw UsageError(exact ? "compare --exact V takes one image, TEST.exr (got " +
                                     std::to_string(args.positional.size()) + "; see lumina compare --help)"
                               : "compare takes two images, REF.exr and TEST.exr (got " +
                                     std::to_string(args.positional.size()) + "; see lumina compare --help)");
    }
    const double exactValue = exact ? args.getDouble("exact", 0.0) : 0.0;
    if (exact && !(std::isfinite(exactValue) && exactValue >= 0.0 && exactValue <= 1e30)) {
        throw UsageError("--exact: " + args.get("exact") + " is not a radiance in [0, 1e30]");
    }
    const std::string refPath = exact ? "exact " + args.get("exact") : args.positional[0];
    const std::string& testPath = args.positional[images - 1];
    measure::CompareOptions options;
    options.flip.pixelsPerDegree = args.getDouble("ppd", measure::kDefaultPixelsPerDegree);
    if (options.flip.pixelsPerDegree < 1.0 || options.flip.pixelsPerDegree > 1000.0) {
        throw UsageError("--ppd: " + args.get("ppd") + " is out of range [1, 1000]");
    }
    options.display.exposureEv = float(args.getDouble("exposure", 0.0));
    if (options.display.exposureEv < -64.0f || options.display.exposureEv > 64.0f) {
        throw UsageError("--exposure: " + args.get("exposure") + " is out of range [-64, 64]");
    }

    const image::Image test = image::readExr(testPath);
    const image::Image reference = exact ? constantImage(test, float(exactValue)) : image::readExr(refPath);
    if (!reference.sameSize(test)) {
        throw image::ImageError(refPath + " is " + image::sizeString(reference) + " but " + testPath +
                                " is " + image::sizeString(test) + ": images must have the same size");
    }
    const measure::CompareResult result = measure::compareImages(reference, test, options);
    printReport(refPath, testPath, reference, test, result, options);

    if (args.has("heatmap")) {
        const std::string path = args.get("heatmap");
        image::writeHeatmapPng(path, result.flip.errorMap, result.width, result.height, 1.0f);
        std::cout << "  heat map   " << path << " (FLIP error 0..1, magma colour map)\n";
    }
    if (args.has("json")) {
        const std::string path = args.get("json");
        writeText(path, measure::compareReportJson(result, refPath, testPath, options));
        std::cout << "  json       " << path << '\n';
    }
    if (result.hasNonFinite()) {
        std::cerr << "compare: FAILED: non-finite pixels";
        if (result.reference.total() != 0) {
            std::cerr << " - " << refPath << ": " << counts(result.reference);
        }
        if (result.test.total() != 0) {
            std::cerr << " - " << testPath << ": " << counts(result.test);
        }
        std::cerr << " (left out of relMSE, RMSE and PSNR)\n";
        return 1;
    }
    return 0;
}

} // namespace

Command compareCommand() {
    return {
        .name = "compare",
        .summary = "measure a test image against a reference (relMSE, RMSE, PSNR, FLIP)",
        .usage = "lumina compare REF.exr TEST.exr [--heatmap diff.png] [--json out.json] [--ppd N] "
                 "[--exposure EV]\n       lumina compare --exact V TEST.exr [...]",
        .description =
            "Reads two OpenEXR images of the same size (R, G, B required) and prints, on linear radiance, "
            "relMSE = mean (x-r)^2/(r^2+0.01) over pixels and R,G,B, RMSE and the pixel with the largest "
            "relMSE; on both images tonemapped alike (exposure, ACES fit, sRGB), PSNR with peak 1 and the "
            "mean and largest LDR-FLIP error (Andersson et al. 2020); and the NaN/Inf pixel count of each "
            "image. With --exact V the reference is the image of constant radiance V (a furnace's exact "
            "answer) and only TEST.exr is read. Exit code 0 when both images are finite, 1 on NaN/Inf pixels "
            "or a read/write error, 2 on "
            "a usage error. docs/measurement.md defines every number.",
        .flags = {{"heatmap", "PATH", "write the FLIP error map as a magma-coloured PNG"},
                  {"json", "PATH", "write every figure as JSON"},
                  {"ppd", "N",
                   "FLIP observer's pixels per degree (default 67.02: 0.7 m from a 0.7 m 4K monitor)"},
                  {"exposure", "EV", "exposure in stops before tonemapping, for PSNR and FLIP (default 0)"},
                  {"exact", "V",
                   "compare TEST.exr against constant radiance V in R, G, B instead of REF.exr (0..1e30)"}},
        .run = runCompare};
}

} // namespace lumina::app
