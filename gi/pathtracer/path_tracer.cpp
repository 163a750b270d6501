#include "gi/pathtracer/path_tracer.h"

#include "gi/core/camera.h"
#include "shaders/common/constants_shared.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace lumina::gi {

namespace {

constexpr uint32_t kGroupSize = LUMINA_SCREEN_GROUP_SIZE; // numthreads of pathtracer/path_trace
// The relMSE regulariser of docs/measurement.md: relMSE = mean((x - r)^2 / (r^2 + 0.01)).
constexpr double kRelativeErrorEpsilon = 0.01;

rhi::BufferHandle pixelBuffer(rhi::IDevice& device, uint64_t count, uint32_t stride, const char* name) {
    return device.createBuffer({.size = count * stride,
                                .structStride = stride,
                                .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                .debugName = name});
}

} // namespace

double relativeStandardError(std::span<const gpu::float4> mean, std::span<const gpu::float4> m2,
                             uint32_t samples) {
    if (samples < 2 || mean.empty()) {
        return std::numeric_limits<double>::infinity();
    }
    const double n = samples;
    double sum = 0.0;
    for (size_t i = 0; i < mean.size(); ++i) {
        const double varianceOfMean = std::max(double(m2[i].w), 0.0) / (n * (n - 1.0));
        const double l = mean[i].w;
        sum += std::sqrt(varianceOfMean / (l * l + kRelativeErrorEpsilon));
    }
    return sum / double(mean.size());
}

PathTracer::PathTracer(rhi::IDevice& device, const PathTracerScene& traced, const scene::Scene& scene,
                       const PathTracerSettings& settings)
    : device_(device), traced_(traced), settings_(settings) {
    if (settings_.width == 0 || settings_.height == 0) {
        settings_.width = scene.image.width;
        settings_.height = scene.image.height;
    }
    if (settings_.width == 0 || settings_.height == 0 || pixelCount() > (uint64_t(1) << 28)) {
        throw rhi::Error("path tracer: image size " + std::to_string(settings_.width) + "x" +
                         std::to_string(settings_.height) + " is empty or too large");
    }
    if (settings_.rowCount == 0 && settings_.firstRow < settings_.height) {
        settings_.rowCount = settings_.height - settings_.firstRow;
    }
    if (settings_.rowCount == 0 || uint64_t(settings_.firstRow) + settings_.rowCount > settings_.height) {
        throw rhi::Error("path tracer: rows " + std::to_string(settings_.firstRow) + " + " +
                         std::to_string(settings_.rowCount) + " outside the image's " +
                         std::to_string(settings_.height) + " rows");
    }
    gpu::PathTraceConstants constants{};
    constants.camera = makeGpuCamera(scene.camera, settings_.width, settings_.height);
    const uint32_t flags =
        (settings_.jitter ? LUMINA_PT_FLAG_JITTER : 0u) | (settings_.aovs ? LUMINA_PT_FLAG_AOVS : 0u);
    constants.lightCount = traced.stats().lights;
    constants.emitterCount = traced.stats().emitters;
    constants.maxBounces = settings_.maxBounces;
    constants.flags = flags;
    constants.width = settings_.width;
    constants.height = settings_.height;
    constants.seed = settings_.seed;
    constants.rouletteStartBounce = settings_.rouletteStartBounce;
    constants_ = rhi::createBufferWithData(device,
                                           {.size = sizeof(constants),
                                            .usage = rhi::BufferUsage::Constant,
                                            .debugName = "path tracer: constants"},
                                           &constants, sizeof(constants));

    const uint64_t pixels = pixelCount();
    mean_ = pixelBuffer(device, pixels, sizeof(gpu::float4), "path tracer: mean");
    m2_ = pixelBuffer(device, pixels, sizeof(gpu::float4), "path tracer: squared deviations");
    counts_ = pixelBuffer(device, pixels, sizeof(gpu::uint2), "path tracer: counts");
    aovs_ = pixelBuffer(device, settings_.aovs ? pixels : 1, sizeof(gpu::PtPixelAovs), "path tracer: aovs");
}

void PathTracer::recordSamples(FrameContext& frame, uint32_t count) {
    const uint32_t width = settings_.width;
    const uint32_t endRow = settings_.firstRow + settings_.rowCount;
    // Bands of whole rows, a multiple of the group height, of at most maxPixelsPerDispatch.
    uint32_t bandRows = std::max(settings_.maxPixelsPerDispatch / width, 1u);
    bandRows = std::max(bandRows / kGroupSize * kGroupSize, kGroupSize);
    const GpuScene& scene = traced_.gpuScene();
    for (uint32_t s = 0; s < count; ++s) {
        // A band's last group may run past endRow into rows another shard owns: those pixels
        // land in this tracer's buffers only, and readResult never returns them.
        for (uint32_t y = settings_.firstRow; y < endRow; y += bandRows) {
            frame.compute("path tracer: sample", "pathtracer/path_trace")
                .constantBuffer(0, constants_)
                .read(0, traced_.bvhNodes)
                .read(1, traced_.bvhTriangles)
                .read(2, traced_.triangles)
                .read(3, scene.vertices)
                .read(4, scene.indices)
                .read(5, scene.instances)
                .read(6, scene.materials)
                .read(7, traced_.emitters)
                .read(8, traced_.emitterAlias)
                .read(9, traced_.lights)
                .read(10, scene.textures)
                .read(11, scene.sky)
                .sampler(0, scene.materialSampler)
                .write(0, mean_)
                .write(1, m2_)
                .write(2, counts_)
                .write(3, aovs_)
                .constants(gpu::PathTracePassConstants{samples_, 0u, y, 0u})
                .dispatchThreads(width, std::min(bandRows, endRow - y), {kGroupSize, kGroupSize});
        }
        ++samples_;
    }
}

template <typename T>
std::span<const T> PathTracer::tracedRows(const std::vector<T>& pixels) const {
    const size_t first = size_t(settings_.firstRow) * settings_.width;
    return std::span<const T>(pixels).subspan(first, size_t(settings_.rowCount) * settings_.width);
}

double PathTracer::meanRelativeStandardError() const {
    const auto mean = rhi::readBufferAs<gpu::float4>(device_, *mean_);
    const auto m2 = rhi::readBufferAs<gpu::float4>(device_, *m2_);
    return relativeStandardError(tracedRows(mean), tracedRows(m2), samples_);
}

PathTracerResult PathTracer::readResult() const {
    const auto meanBuffer = rhi::readBufferAs<gpu::float4>(device_, *mean_);
    const auto m2Buffer = rhi::readBufferAs<gpu::float4>(device_, *m2_);
    const auto countsBuffer = rhi::readBufferAs<gpu::uint2>(device_, *counts_);
    const std::span<const gpu::float4> mean = tracedRows(meanBuffer), m2 = tracedRows(m2Buffer);
    const std::span<const gpu::uint2> counts = tracedRows(countsBuffer);

    PathTracerResult result;
    result.samples = samples_;
    std::vector<std::string> names = {"R", "G", "B", "variance.R", "variance.G", "variance.B"};
    if (settings_.aovs) {
        for (const char* layer : {"albedo", "direct", "indirect"}) {
            for (const char* c : {".R", ".G", ".B"}) {
                names.push_back(std::string(layer) + c);
            }
        }
        for (const char* c : {"normal.X", "normal.Y", "normal.Z"}) {
            names.push_back(c);
        }
    }
    result.image = image::Image(settings_.width, settings_.rowCount, names);
    const double n = samples_;
    const double varianceScale = samples_ > 1 ? 1.0 / (n * (n - 1.0)) : 0.0;
    auto plane = [&](const char* name) { return result.image.channel(name); };
    std::span<float> r = plane("R"), g = plane("G"), b = plane("B");
    std::span<float> vr = plane("variance.R"), vg = plane("variance.G"), vb = plane("variance.B");
    for (size_t i = 0; i < mean.size() && i < r.size(); ++i) {
        r[i] = mean[i].x;
        g[i] = mean[i].y;
        b[i] = mean[i].z;
        vr[i] = float(std::max(double(m2[i].x), 0.0) * varianceScale);
        vg[i] = float(std::max(double(m2[i].y), 0.0) * varianceScale);
        vb[i] = float(std::max(double(m2[i].z), 0.0) * varianceScale);
        result.rays += counts[i].x;
        result.nonFiniteSamples += counts[i].y;
    }
    if (settings_.aovs) {
        const auto aovBuffer = rhi::readBufferAs<gpu::PtPixelAovs>(device_, *aovs_);
        const std::span<const gpu::PtPixelAovs> aovs = tracedRows(aovBuffer);
        auto copy3 = [&](const char* x, const char* y, const char* z, gpu::float4 gpu::PtPixelAovs::*member) {
            std::span<float> px = plane(x), py = plane(y), pz = plane(z);
            for (size_t i = 0; i < aovs.size() && i < px.size(); ++i) {
                const gpu::float4& v = aovs[i].*member;
                px[i] = v.x;
                py[i] = v.y;
                pz[i] = v.z;
            }
        };
        copy3("albedo.R", "albedo.G", "albedo.B", &gpu::PtPixelAovs::albedo);
        copy3("normal.X", "normal.Y", "normal.Z", &gpu::PtPixelAovs::normal);
        copy3("direct.R", "direct.G", "direct.B", &gpu::PtPixelAovs::direct);
        copy3("indirect.R", "indirect.G", "indirect.B", &gpu::PtPixelAovs::indirect);
    }
    result.meanRelativeStandardError = relativeStandardError(mean, m2, samples_);
    return result;
}

} // namespace lumina::gi
