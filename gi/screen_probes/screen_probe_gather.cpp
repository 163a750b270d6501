#include "gi/screen_probes/screen_probe_gather.h"

#include "gi/core/camera.h"
#include "rhi/transfer.h"
#include "shaders/screen_probes/screen_probe_shared.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

void checkVoxelLighting(const VoxelLighting& voxels) {
    if (!voxels.texture) {
        return;
    }
    const rhi::TextureDesc& desc = voxels.texture->desc();
    if (desc.dimension != rhi::TextureDimension::Texture3D || desc.format != rhi::Format::RGBA16_FLOAT) {
        throw std::invalid_argument("screen probes: voxel lighting '" + desc.debugName +
                                    "' must be an RGBA16F 3D texture");
    }
    const glm::vec3 extent = voxels.boxMax - voxels.boxMin;
    if (!(extent.x > 0.0f && extent.y > 0.0f && extent.z > 0.0f)) {
        throw std::invalid_argument("screen probes: voxel lighting box has extent (" +
                                    std::to_string(extent.x) + ", " + std::to_string(extent.y) + ", " +
                                    std::to_string(extent.z) + "): expected all > 0");
    }
}

} // namespace

ScreenProbeGather::ScreenProbeGather(rhi::IDevice& device, uint32_t width, uint32_t height,
                                     ScreenProbeSettings settings)
    : settings_(settings), resources_(ScreenProbeResources::create(device, width, height, settings)) {}

uint32_t ScreenProbeGather::adaptiveProbesWanted(rhi::IDevice& device) const {
    return resources_.adaptiveRows > 0 ? rhi::readBufferAs<uint32_t>(device, *resources_.adaptiveWanted).at(0)
                                       : 0;
}

uint32_t ScreenProbeGather::brdfRays() const {
    return uint32_t(std::lround(float(resources_.raysPerProbe) * settings_.brdfRayFraction));
}

ScreenProbeGather::TraceRange ScreenProbeGather::traceRange(const ScreenProbeInputs& inputs) const {
    const gpu::SdfSceneInfo sdf = inputs.sdf.sceneInfo();
    const float diagonal = glm::length(sdf.globalMax - sdf.globalMin);
    TraceRange range;
    range.maxDistance = settings_.maxTraceDistance > 0.0f ? settings_.maxTraceDistance : diagonal;
    if (inputs.surfaceCache) {
        const float near =
            settings_.nearFieldDistance.value_or(ScreenProbeSettings::kNearFieldGridFraction * diagonal);
        range.nearField = std::min(near, range.maxDistance);
    }
    return range;
}

void ScreenProbeGather::uploadConstants(rhi::ICommandList& commands, const ScreenProbeInputs& inputs,
                                        const gpu::GpuCamera& camera, const TraceRange& range) {
    const ScreenProbeResources& r = resources_;
    const float voxel = inputs.sdf.sceneInfo().globalVoxelSize;
    const uint32_t brdfRays = this->brdfRays();
    // Far hits read the caller's volume, else the surface cache's (with its own lookup).
    const bool cacheVoxels = !inputs.voxelLighting.texture && inputs.surfaceCache;
    glm::vec3 voxelMin = inputs.voxelLighting.boxMin, voxelMax = inputs.voxelLighting.boxMax;

    uint32_t flags = 0;
    if (previousCamera_) {
        flags |= LUMINA_SP_FLAG_PROBE_HISTORY | LUMINA_SP_FLAG_SCREEN_HISTORY;
    }
    if (inputs.voxelLighting.texture || cacheVoxels) {
        flags |= LUMINA_SP_FLAG_VOXEL_LIGHTING;
    }
    if (range.nearField > 0.0f) {
        flags |= LUMINA_SP_FLAG_NEAR_FIELD;
    }
    gpu::ScreenProbeConstants c{};
    if (inputs.surfaceCache) {
        c.voxelGrid = inputs.surfaceCache->voxelGrid;
    }
    if (cacheVoxels) {
        flags |= LUMINA_SP_FLAG_VOXEL_GRID;
        voxelMin = c.voxelGrid.boxMin;
        voxelMax = voxelMin + glm::vec3(c.voxelGrid.dims) * c.voxelGrid.voxelSize;
    }
    c.camera = camera;
    c.previousCamera = previousCamera_ ? *previousCamera_ : camera;
    c.probeGrid = gpu::uint2(r.gridWidth, r.gridHeight);
    c.probeSpacing = settings_.probeSpacing;
    c.probeCount = r.probeCount;
    c.uniformProbeCount = r.uniformProbeCount;
    c.adaptiveSpacing = r.adaptiveSpacing;
    c.imageSize = gpu::uint2(r.width, r.height);
    c.frameIndex = uint32_t(frames_);
    c.flags = flags;
    c.raysPerProbe = r.raysPerProbe;
    c.brdfRays = brdfRays;
    c.lightingRays = r.raysPerProbe - brdfRays;
    c.voxelMin = voxelMin;
    c.voxelMax = voxelMax;
    c.maxTraceDistance = range.maxDistance;
    c.coneTanHalfAngle = std::tan(settings_.coneHalfAngle);
    c.originBias = settings_.originBiasVoxels * voxel;
    c.slideMarginVoxels = 0.25f * settings_.originBiasVoxels;
    c.nearFieldDistance = range.nearField;
    c.probeHistoryBlend = settings_.probeHistoryBlend;
    c.outlierClamp = settings_.outlierClamp;
    c.outlierClampTexelShare = settings_.outlierClampTexelShare;
    c.screenHistoryBlend = settings_.screenHistoryBlend;
    c.lightingPdfFloor = settings_.lightingPdfFloor;
    c.filterPlaneScale = settings_.filterPlaneScale;
    c.filterNormalPower = settings_.filterNormalPower;
    c.historyPlaneTolerance = settings_.historyPlaneTolerance;
    c.historyNormalTolerance = settings_.historyNormalTolerance;
    c.changeRegionCount = uint32_t(changes_.size());
    for (size_t i = 0; i < changes_.size(); ++i) {
        c.changeRegions[i].boxMin = changes_[i].box.min;
        c.changeRegions[i].historyKept = changes_[i].keep;
        c.changeRegions[i].boxMax = changes_[i].box.max;
    }
    changes_.clear();
    commands.writeBuffer(*r.constants, &c, sizeof(c));
}

void ScreenProbeGather::invalidateHistory(const scene::Bounds& region, float keep) {
    if (region.empty()) {
        return;
    }
    keep = std::clamp(keep, 0.0f, 1.0f);
    if (changes_.size() == LUMINA_SP_MAX_CHANGE_REGIONS) {
        // Full: the last slot grows to hold this one too, keeping the smaller share.
        changes_.back().box.extend(region);
        changes_.back().keep = std::min(changes_.back().keep, keep);
        return;
    }
    changes_.push_back({region, keep});
}

void ScreenProbeGather::record(FrameContext& frame, const ScreenProbeInputs& inputs) {
    const rhi::TextureDesc& size = inputs.gbuffer.position->desc();
    if (size.width != resources_.width || size.height != resources_.height) {
        throw std::invalid_argument("screen probes: GBuffer is " + std::to_string(size.width) + "x" +
                                    std::to_string(size.height) + ", the gather was made for " +
                                    std::to_string(resources_.width) + "x" +
                                    std::to_string(resources_.height));
    }
    if (!inputs.sky) {
        throw std::invalid_argument("screen probes: no sky texture (a black sky is a 1x1 texture of zeros)");
    }
    checkVoxelLighting(inputs.voxelLighting);
    if (inputs.surfaceCache) {
        checkSurfaceCacheView(*inputs.surfaceCache);
    }
    if (!voxelFallbackCleared_) {
        const uint16_t zeros[4] = {0, 0, 0, 0}; // RGBA16F zeros
        frame.commands().writeTexture(*resources_.noVoxelLighting, {}, zeros);
        voxelFallbackCleared_ = true;
    }
    current_ ^= 1u;
    const gpu::GpuCamera camera = makeGpuCamera(inputs.camera, resources_.width, resources_.height);
    const TraceRange range = traceRange(inputs);
    uploadConstants(frame.commands(), inputs, camera, range);

    rhi::TextureHandle voxels = resources_.noVoxelLighting;
    if (inputs.voxelLighting.texture) {
        voxels = inputs.voxelLighting.texture;
    } else if (inputs.surfaceCache) {
        voxels = inputs.surfaceCache->voxelLighting;
    }
    const ScreenProbeView view{.resources = resources_,
                               .gbuffer = inputs.gbuffer,
                               .sdf = inputs.sdf,
                               .voxelLighting = voxels,
                               .surfaceCache = inputs.surfaceCache ? &*inputs.surfaceCache : nullptr,
                               .sky = inputs.sky,
                               .current = current_};
    placement_.record(frame, view);
    if (resources_.adaptiveRows > 0) {
        adaptivePlacement_.record(frame, view);
        adaptiveAllocation_.record(frame, view);
    } else {
        frame.skip(ScreenProbeAdaptivePlacementPass::kName, "adaptiveProbeFraction is 0");
        frame.skip(ScreenProbeAdaptiveAllocationPass::kName, "adaptiveProbeFraction is 0");
    }
    // A strategy that draws no rays needs no table (spMisWeight leaves it out).
    if (brdfRays() > 0) {
        brdfPdf_.record(frame, view);
    } else {
        frame.skip(ProbeBrdfPdfPass::kName,
                   "no BRDF rays: all " + std::to_string(resources_.raysPerProbe) + " from the lighting PDF");
    }
    if (brdfRays() < resources_.raysPerProbe) {
        lightingPdf_.record(frame, view);
    } else {
        frame.skip(ProbeLightingPdfPass::kName,
                   "no lighting rays: all " + std::to_string(resources_.raysPerProbe) + " from the BRDF PDF");
    }
    rayGeneration_.record(frame, view);
    nearFieldTraced_ = range.nearField > 0.0f;
    if (nearFieldTraced_) {
        traceNearField_.record(frame, view);
    } else {
        frame.skip(ProbeTraceNearFieldPass::kName,
                   inputs.surfaceCache ? "nearFieldDistance is 0" : "no surface cache given");
    }
    // A near field that reaches the rays' end leaves its misses to the sky: no far field.
    if (nearFieldTraced_ && range.nearField >= range.maxDistance) {
        frame.skip(ProbeTraceFarFieldPass::kName, "the near field reaches the trace's end");
    } else {
        traceFarField_.record(frame, view);
    }
    rayShading_.record(frame, view);
    composite_.record(frame, view);
    temporal_.record(frame, view);
    spatialFilter_.record(frame, view);
    shIrradiance_.record(frame, view);
    gather_.record(frame, view);
    screenTemporal_.record(frame, view);

    previousCamera_ = camera;
    ++frames_;
}

} // namespace lumina::gi
