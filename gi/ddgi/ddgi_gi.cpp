#include "gi/ddgi/ddgi_gi.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <numbers>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

const DdgiSettings& validated(const DdgiSettings& settings) {
    settings.validate();
    return settings;
}

std::vector<DdgiVolumePlacement> firstPlacement(const DdgiSettings& settings, const scene::Scene& scene) {
    const std::vector<DdgiVolumePlacement> volumes =
        placeDdgiVolumes(validated(settings), scene.worldBounds(), scene.camera.position);
    const DdgiAtlasLayout layout = ddgiAtlasLayout(volumes);
    // One trace group per probe, along x.
    if (layout.probes > 65535) {
        throw std::invalid_argument("ddgi: " + std::to_string(layout.probes) +
                                    " probes over every volume (at most 65535)");
    }
    return volumes;
}

// A rotation drawn uniformly (Shoemake's method: a uniform unit quaternion from three uniforms).
glm::mat3 randomRotation(std::mt19937& random) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float u1 = u(random), u2 = 2.0f * std::numbers::pi_v<float> * u(random),
                u3 = 2.0f * std::numbers::pi_v<float> * u(random);
    const float a = std::sqrt(1.0f - u1), b = std::sqrt(u1);
    return glm::mat3_cast(glm::quat(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3)));
}

} // namespace

DdgiGi::DdgiGi(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene, uint32_t width,
               uint32_t height, const DdgiSettings& settings)
    : settings_(settings), scene_(device, scene, gpuScene, settings), sceneBox_(scene.worldBounds()),
      volumes_(firstPlacement(settings, scene)), beforeProbes_(device.allocatedMemoryBytes()),
      resources_(
          DdgiResources::create(device, ddgiAtlasLayout(volumes_), settings.raysPerProbe, width, height)),
      afterProbes_(device.allocatedMemoryBytes()), scrolls_(volumes_.size(), glm::uvec3(0)),
      random_(settings.seed) {}

bool DdgiGi::uploadConstants(rhi::ICommandList& commands, const scene::Camera& camera) {
    const std::vector<DdgiVolumePlacement> placed = placeDdgiVolumes(settings_, sceneBox_, camera.position);
    const gpu::SdfSceneInfo sdf = scene_.sdf().sceneInfo();
    const float diagonal = glm::length(sdf.globalMax - sdf.globalMin);
    const float nearField =
        settings_.nearFieldDistance > 0.0f ? std::min(settings_.nearFieldDistance, diagonal) : diagonal;
    gpu::DdgiConstants c{};
    bool anyReset = false;
    for (uint32_t v = 0; v < placed.size(); ++v) {
        // A cascade that moved with the camera keeps the probes that stay inside it; those of
        // the planes it gained start afresh.
        DdgiScroll scroll = scrollDdgiVolume(volumes_[v], placed[v], scrolls_[v]);
        if (updates_ == 0) {
            scroll = {.reset = true};
        }
        scrolls_[v] = scroll.offset;
        anyReset = anyReset || scroll.reset || scroll.enteredMin != scroll.enteredMax;
        c.volumes[v] = ddgiVolumeInfo(placed[v], resources_.layout, v, settings_.maxOffset,
                                      scroll.reset ? LUMINA_DDGI_VOLUME_RESET : 0u, scroll);
    }
    volumes_ = placed;
    const glm::mat3 rotation = randomRotation(random_);
    for (int row = 0; row < 3; ++row) {
        c.rotation[row] = gpu::float4(rotation[0][row], rotation[1][row], rotation[2][row], 0.0f);
    }
    c.raysPerProbe = settings_.raysPerProbe;
    c.fixedRays = LUMINA_DDGI_FIXED_RAYS;
    c.volumeCount = uint32_t(placed.size());
    c.probeCount = resources_.layout.probes;
    c.nearFieldDistance = nearField;
    c.maxTraceDistance = diagonal;
    c.backfaceFraction = settings_.backfaceFraction;
    c.minFrontfaceDistance = settings_.minFrontfaceDistance;
    c.hysteresis = settings_.hysteresis;
    c.changedHysteresis = settings_.changedHysteresis;
    c.largeChangeRatio = settings_.largeChangeRatio;
    c.distanceSharpness = settings_.distanceSharpness;
    c.normalBias = settings_.normalBias;
    c.viewBias = settings_.viewBias;
    c.relocation = settings_.relocation ? 1u : 0u;
    c.classification = settings_.classification ? 1u : 0u;
    c.irradianceAtlasSize = gpu::uint2(resources_.irradianceWidth(), resources_.irradianceHeight());
    c.distanceAtlasSize = gpu::uint2(resources_.distanceWidth(), resources_.distanceHeight());
    c.cameraPosition = camera.position;
    c.imageSize = gpu::uint2(resources_.width, resources_.height);
    c.voxelGrid = scene_.surfaceCache().voxelLighting().grid();
    commands.writeBuffer(*resources_.constants, &c, sizeof(c));
    return anyReset;
}

void DdgiGi::recordProbeUpdate(FrameContext& frame, const DeferredRenderer& deferred,
                               const scene::Camera& camera) {
    scene_.record(frame, deferred, camera);
    if (uploadConstants(frame.commands(), camera)) {
        reset_.record(frame, resources_);
    } else {
        frame.skip(DdgiResetPass::kName, "no volume new or moved");
    }
    trace_.record(frame, resources_, scene_);
    blendIrradiance_.record(frame, resources_);
    blendDistance_.record(frame, resources_);
    relocate_.record(frame, resources_, scene_.sdf());
    classify_.record(frame, resources_);
}

bool DdgiGi::recordBesideRaster(FrameContext& async, const DeferredRenderer& deferred,
                                const scene::Camera& camera) {
    if (!scene_.recordIsComputeOnly(deferred, camera)) {
        return false;
    }
    recordProbeUpdate(async, deferred, camera);
    probesRecordedBesideRaster_ = true;
    return true;
}

void DdgiGi::record(FrameContext& frame, const DeferredRenderer& deferred, const scene::Camera& camera) {
    if (!probesRecordedBesideRaster_) {
        recordProbeUpdate(frame, deferred, camera);
    }
    probesRecordedBesideRaster_ = false;
    sample_.record(frame, resources_, deferred.gbuffer());
    ++updates_;
}

void DdgiGi::moveInstance(uint32_t instance, const glm::mat4& transform, const scene::Bounds&,
                          const scene::Bounds&, std::span<const scene::Light> lights) {
    // The probes re-judge their place and state every update, and a large change in what their
    // rays see lowers the hysteresis: nothing of theirs to drop.
    scene_.moveInstance(instance, transform, lights);
}

void DdgiGi::setLights(std::span<const scene::Light> lights, uint64_t lightsVersion,
                       std::span<const scene::Bounds>) {
    scene_.setLights(lights, lightsVersion);
}

void DdgiGi::instanceMaterialChanged(uint32_t instance, const scene::Bounds&) {
    scene_.instanceMaterialChanged(instance);
}

std::vector<GiMemoryPart> DdgiGi::memory() const {
    std::vector<GiMemoryPart> parts = scene_.memory();
    parts.push_back({"DDGI probe volumes", afterProbes_ - beforeProbes_});
    return parts;
}

std::vector<GiDebugTexture> DdgiGi::debugTextures() const {
    return {{"ddgi: irradiance E", resources_.sampled, 1.0f},
            {"ddgi: irradiance atlas (E^(1/5))", resources_.irradiance, 1.0f},
            {"ddgi: distance atlas (cells)", resources_.distance, 0.25f}};
}

DdgiProbeCounts DdgiGi::probeCounts(rhi::IDevice& device) const {
    DdgiProbeCounts counts;
    for (const gpu::DdgiProbe& probe : rhi::readBufferAs<gpu::DdgiProbe>(device, *resources_.probes)) {
        const float state = probe.offsetAndState.w;
        if (state == LUMINA_DDGI_PROBE_INACTIVE) {
            ++counts.inactive;
        } else if (state == LUMINA_DDGI_PROBE_ACTIVE) {
            ++counts.active;
        } else {
            ++counts.fresh;
        }
    }
    return counts;
}

} // namespace lumina::gi
