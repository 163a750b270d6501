#include "gi/sh_grid/sh_grid_gi.h"

#include "rhi/transfer.h"
#include "shaders/sh_grid/sh_grid_shared.h"

#include <algorithm>

namespace lumina::gi {

namespace {

const ShGridSettings& validated(const ShGridSettings& settings) {
    settings.validate();
    return settings;
}

// Probes within one cell of a change see it change most.
float changeMargin(const ShGridLayout& layout) {
    return std::max({layout.spacing.x, layout.spacing.y, layout.spacing.z});
}

} // namespace

ShGridGi::ShGridGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
                   uint32_t height, const ShGridSettings& settings)
    : settings_(validated(settings)), beforeGrid_(device.allocatedMemoryBytes()),
      resources_(ShGridResources::create(device, fitShGrid(settings, scene.worldBounds()), width, height)),
      bake_(device, scene, gpuScene, settings), afterGrid_(device.allocatedMemoryBytes()),
      schedule_(resources_.layout, settings.sweeps) {
    if (!settings.loadPath.empty()) {
        loaded_ = loadShGrid(settings.loadPath);
        requireSameGrid(resources_.layout, loaded_->layout, settings.loadPath);
        schedule_.settle();
    }
}

void ShGridGi::uploadInitial(rhi::ICommandList& commands) {
    std::vector<gpu::float4> data(size_t(resources_.layout.probes()) * LUMINA_SH_GRID_COEFFICIENTS,
                                  gpu::float4(0.0f));
    if (loaded_) {
        for (size_t i = 0; i < data.size(); ++i) {
            data[i] = gpu::float4(loaded_->coefficients[i], 0.0f);
        }
        loaded_.reset();
    }
    commands.writeBuffer(*resources_.coefficients, data.data(), data.size() * sizeof(gpu::float4));
    // A loaded grid's own sweeps are not in its file: bakes after a change start from the grid.
    commands.writeBuffer(*resources_.bounceSource, data.data(), data.size() * sizeof(gpu::float4));

    const glm::vec2 window = shGridWindow(settings_.ringingWindow);
    gpu::ShGridConstants c{};
    c.origin = resources_.layout.origin;
    c.probeCount = resources_.layout.probes();
    c.spacing = resources_.layout.spacing;
    c.windowBand1 = window.x;
    c.counts = resources_.layout.counts;
    c.windowBand2 = window.y;
    c.width = resources_.width;
    c.height = resources_.height;
    commands.writeBuffer(*resources_.constants, &c, sizeof(c));
    uploaded_ = true;
}

void ShGridGi::record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera&) {
    if (!uploaded_) {
        uploadInitial(frame.commands());
    }
    std::vector<uint32_t> probes = schedule_.next(settings_.probesPerFrame);
    if (probes.empty() && !frame.mayReuse(kBakeName)) {
        // Forced: the budget's worth of probes bakes again, in turn round the grid, from the last
        // sweep's bounce source: to the values they hold.
        const uint32_t count = schedule_.probeCount();
        for (uint32_t i = 0; i < settings_.probesPerFrame && i < count; ++i) {
            probes.push_back((forcedNext_ + i) % count);
        }
        forcedNext_ = count ? uint32_t((forcedNext_ + probes.size()) % count) : 0;
        std::sort(probes.begin(), probes.end());
    }
    if (schedule_.batchBeganSweep()) {
        const uint64_t bytes = resources_.coefficients->desc().size;
        frame.commands().copyBuffer(*resources_.bounceSource, 0, *resources_.coefficients, 0, bytes);
    }
    lastBaked_ = uint32_t(probes.size());
    if (probes.empty()) {
        frame.skipReused(kBakeName, "no probe dirty or owed a bake (nothing changed)");
    } else {
        bake_.record(frame, deferred, resources_, probes);
    }
    sample_.record(frame, resources_, deferred.gbuffer());
}

void ShGridGi::moveInstance(uint32_t, const glm::mat4&, const scene::Bounds& before,
                            const scene::Bounds& after, std::span<const scene::Light>) {
    const float margin = changeMargin(resources_.layout);
    schedule_.changed(before, margin);
    schedule_.changed(after, margin);
}

void ShGridGi::setLights(std::span<const scene::Light>, uint64_t, std::span<const scene::Bounds> reach) {
    const float margin = changeMargin(resources_.layout);
    for (const scene::Bounds& box : reach) {
        schedule_.changed(box, margin);
    }
}

void ShGridGi::instanceMaterialChanged(uint32_t, const scene::Bounds& reach) {
    schedule_.changed(reach, changeMargin(resources_.layout));
}

std::vector<GiMemoryPart> ShGridGi::memory() const {
    return {{"SH probe grid", afterGrid_ - beforeGrid_}};
}

std::vector<GiDebugTexture> ShGridGi::debugTextures() const {
    return {{"sh grid: irradiance E", resources_.sampled, 1.0f},
            {"sh grid: last baked cube face (radiance)", bake_.lastFaceRadiance(), 1.0f}};
}

ShGridFile ShGridGi::readGrid(rhi::IDevice& device) const {
    ShGridFile grid{.layout = resources_.layout, .coefficients = {}};
    for (const gpu::float4& c : rhi::readBufferAs<gpu::float4>(device, *resources_.coefficients)) {
        grid.coefficients.emplace_back(c);
    }
    return grid;
}

} // namespace lumina::gi
