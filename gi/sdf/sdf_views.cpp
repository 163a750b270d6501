#include "gi/sdf/sdf_views.h"

#include "gi/core/camera.h"
#include "gi/image/colormap.h"
#include "shaders/common/constants_shared.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace lumina::sdf {
namespace {

// Far field: the truncated global SDF advances at most maxDistance (8 voxels by default) a
// step, and rays cross scenes of 64 voxels and more, often at grazing angles.
constexpr uint32_t kFarMaxSteps = 128;
// Darker level-set line every this many voxels of distance in the slice image.
constexpr float kSliceLevelSpacingVoxels = 2.0f;

} // namespace

const char* fieldName(SdfField field) {
    switch (field) {
    case SdfField::Near:
        return "near field";
    case SdfField::Far:
        return "far field";
    case SdfField::Cone:
        return "cone";
    }
    return "?";
}

gpu::SdfTraceParams defaultTraceParams(SdfField field, float maxDistance) {
    gpu::SdfTraceParams params{};
    params.minStepVoxels = LUMINA_SDF_DEFAULT_MIN_STEP_VOXELS;
    params.hitThresholdVoxels = LUMINA_SDF_DEFAULT_HIT_THRESHOLD_VOXELS;
    params.maxDistance = maxDistance;
    params.maxSteps = LUMINA_SDF_DEFAULT_MAX_STEPS;
    if (field != SdfField::Near) {
        params.maxSteps = kFarMaxSteps;
    }
    return params;
}

SdfCameraTracer::SdfCameraTracer(rhi::IDevice& device, uint32_t width, uint32_t height)
    : width_(width), height_(height) {
    if (width == 0 || height == 0) {
        throw std::invalid_argument("SdfCameraTracer: empty image");
    }
    view_ = device.createBuffer({.size = sizeof(gpu::SdfCameraView),
                                 .usage = rhi::BufferUsage::Constant,
                                 .debugName = "sdf camera view"});
    pixels_ = device.createBuffer({.size = uint64_t(width) * height * sizeof(glm::vec4),
                                   .structStride = sizeof(glm::vec4),
                                   .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                   .debugName = "sdf camera pixels"});
}

void SdfCameraTracer::record(gi::FrameContext& frame, const SceneSdf& sdfs, const scene::Camera& camera,
                             SdfField field, const gpu::SdfTraceParams& params, std::string_view passName,
                             float tanHalfAngle) {
    const gpu::SdfCameraView view{gi::makeGpuCamera(camera, width_, height_)};
    frame.commands().writeBuffer(*view_, &view, sizeof(view));
    const gpu::SdfCameraTraceConstants constants{params, width_, height_, uint32_t(field), tanHalfAngle};
    sdfs.bindForTracing(frame.compute(passName, "sdf/sdf_camera_trace"))
        .constantBuffer(1, view_)
        .write(0, pixels_)
        .constants(constants)
        .dispatchThreads(width_, height_, {LUMINA_SCREEN_GROUP_SIZE, LUMINA_SCREEN_GROUP_SIZE});
}

image::Image SdfCameraTracer::readNormals(rhi::IDevice& device) const {
    const std::vector<glm::vec4> pixels = rhi::readBufferAs<glm::vec4>(device, *pixels_);
    image::Image out(width_, height_, {"R", "G", "B", "t"});
    auto r = out.channel("R"), g = out.channel("G"), b = out.channel("B"), t = out.channel("t");
    for (size_t i = 0; i < out.pixelCount(); ++i) {
        r[i] = pixels[i].x;
        g[i] = pixels[i].y;
        b[i] = pixels[i].z;
        t[i] = pixels[i].w;
    }
    return out;
}

GlobalSdf readGlobalSdf(rhi::IDevice& device, const SceneSdf& sdfs, uint32_t cascade) {
    const GlobalSdfCascadeLayout& layout = sdfs.data().cascades;
    if (cascade >= layout.count) {
        throw std::invalid_argument("readGlobalSdf: cascade " + std::to_string(cascade) + " of " +
                                    std::to_string(layout.count));
    }
    const GlobalSdfSettings settings = sdfs.cascadeGrid(cascade);
    const glm::ivec3 window = sdfs.cascadeWindows()[cascade];
    GlobalSdf grid;
    grid.dims = settings.dims;
    grid.boundsMin = settings.boundsMin;
    grid.voxelSize = settings.voxelSize;
    const std::vector<uint8_t> bytes = rhi::readTexture(device, *sdfs.globalSdf());
    const size_t voxels = size_t(grid.dims.x) * grid.dims.y * grid.dims.z;
    if (bytes.size() != voxels * layout.count * 2 * sizeof(float)) {
        throw std::runtime_error("readGlobalSdf: read " + std::to_string(bytes.size()) + " bytes for " +
                                 std::to_string(layout.count) + " cascade(s) of " + std::to_string(voxels) +
                                 " RG32F voxels");
    }
    grid.distances.resize(voxels);
    grid.instances.resize(voxels);
    // Unwrapped from the cascade's toroidal slab into window order.
    for (uint32_t z = 0; z < grid.dims.z; ++z) {
        for (uint32_t y = 0; y < grid.dims.y; ++y) {
            for (uint32_t x = 0; x < grid.dims.x; ++x) {
                const glm::uvec3 texel = cascadeTexel(layout, window, {x, y, z});
                const size_t t =
                    (size_t(texel.z + cascade * grid.dims.z) * grid.dims.y + texel.y) * grid.dims.x + texel.x;
                float value[2];
                std::memcpy(value, bytes.data() + t * sizeof(value), sizeof(value));
                const size_t i = grid.voxelIndex(x, y, z);
                grid.distances[i] = value[0];
                grid.instances[i] = value[1] >= 0.0f ? uint32_t(value[1]) : kNoInstance;
            }
        }
    }
    return grid;
}

image::Image globalSdfSliceImage(const GlobalSdf& grid, uint32_t z, float maxDistance) {
    if (z >= grid.dims.z) {
        throw std::invalid_argument("globalSdfSliceImage: slice " + std::to_string(z) + " of " +
                                    std::to_string(grid.dims.z));
    }
    image::Image out = image::Image::rgb(grid.dims.x, grid.dims.y);
    for (uint32_t row = 0; row < grid.dims.y; ++row) {
        const uint32_t y = grid.dims.y - 1 - row; // +y up
        for (uint32_t x = 0; x < grid.dims.x; ++x) {
            const float d = grid.distances[grid.voxelIndex(x, y, z)];
            const image::Rgb8 c = image::magma(0.5f + 0.5f * d / maxDistance);
            image::Rgb rgb{c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f};
            const float inVoxels = std::abs(d) / grid.voxelSize;
            if (inVoxels < 0.5f) {
                rgb = {1.0f, 1.0f, 1.0f};
            } else if (std::fmod(inVoxels, kSliceLevelSpacingVoxels) < 0.25f) {
                rgb = {0.6f * rgb.r, 0.6f * rgb.g, 0.6f * rgb.b};
            }
            out.setRgb(x, row, rgb);
        }
    }
    return out;
}

} // namespace lumina::sdf
