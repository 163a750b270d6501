#pragma once
// The SH probe grid technique (docs/sh_grid.md): a grid of probes over the scene, each holding
// L2 (nine coefficients per channel) irradiance, baked from cube maps rendered through the
// deferred renderer's raster passes, blended trilinearly per pixel. The cheap end of the
// run-time-against-error curve. Recorded between the deferred lighting and the composite:
//
//   deferred lighting ─► [bake: per probe 6 x (gbuffer ─► direct light ─► project) ─► combine]
//       ─► sample ─► composite
//
//   ShGridGi gi(device, scene, gpuScene, width, height, shGridPreset("medium", scene));
//   gi.record(frame, deferred, camera);
//   deferred.setIndirect(gi.indirect(), gi.indirectScale());
#include "gi/frame/gi_technique_renderer.h"
#include "gi/sh_grid/sh_grid_bake.h"
#include "gi/sh_grid/sh_grid_file.h"
#include "gi/sh_grid/sh_grid_resources.h"
#include "gi/sh_grid/sh_grid_sample_pass.h"
#include "gi/sh_grid/sh_grid_schedule.h"
#include "gi/sh_grid/sh_grid_settings.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace lumina::gi {

class ShGridGi final : public GiTechniqueRenderer {
public:
    static constexpr const char* kBakeName = "sh grid: bake";

    // `scene` and `gpuScene` must outlive it. std::invalid_argument for bad settings (named);
    // what loadShGrid and requireSameGrid throw for settings.loadPath.
    ShGridGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
             uint32_t height, const ShGridSettings& settings);

    GiTechnique technique() const override { return GiTechnique::ShGrid; }
    void record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera) override;
    // Probes hold world-space irradiance: nothing of the view to forget.
    void resetHistory() override {}
    // Every probe has had the bakes it owes since the last change.
    bool converged() const override { return schedule_.idle(); }

    void moveInstance(uint32_t instance, const glm::mat4& transform, const scene::Bounds& before,
                      const scene::Bounds& after, std::span<const scene::Light> lights) override;
    void setLights(std::span<const scene::Light> lights, uint64_t lightsVersion,
                   std::span<const scene::Bounds> reach) override;
    void instanceMaterialChanged(uint32_t instance, const scene::Bounds& reach) override;

    rhi::TextureHandle indirect() const override { return resources_.sampled; }
    std::vector<GiMemoryPart> memory() const override;
    std::vector<GiDebugTexture> debugTextures() const override;

    // Every probe's coefficients (waits for the GPU): probes x 9, rgb.
    ShGridFile readGrid(rhi::IDevice& device) const;
    const ShGridLayout& layout() const { return resources_.layout; }
    const ShGridResources& resources() const { return resources_; }
    const ShGridSettings& settings() const { return settings_; }
    const ShGridSchedule& schedule() const { return schedule_; }
    // Probes baked by the last record().
    uint32_t lastBaked() const { return lastBaked_; }

private:
    void uploadInitial(rhi::ICommandList& commands);

    ShGridSettings settings_;
    uint64_t beforeGrid_;
    ShGridResources resources_;
    ShGridBake bake_;
    uint64_t afterGrid_;
    ShGridSchedule schedule_;
    ShGridSamplePass sample_;
    std::optional<ShGridFile> loaded_; // uploaded at the first record()
    bool uploaded_ = false;
    uint32_t lastBaked_ = 0;
    uint32_t forcedNext_ = 0; // the next probe a forced bake takes (FrameContext::mayReuse)
};

} // namespace lumina::gi
