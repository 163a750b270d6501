#include "gi/frame/frame_renderer.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) {
                return false;
            }
        }
    }
    return true;
}

void validateLight(const scene::Light& light, size_t index) {
    const std::string name =
        "light " + std::to_string(index) + (light.name.empty() ? "" : " '" + light.name + "'");
    if (!finite(light.color) || glm::any(glm::lessThan(light.color, glm::vec3(0.0f))) ||
        !std::isfinite(light.intensity) || light.intensity < 0.0f) {
        throw std::invalid_argument(name + ": colour and intensity must be finite and not negative");
    }
    if (!finite(light.position) || !finite(light.direction) || glm::length(light.direction) == 0.0f) {
        throw std::invalid_argument(name + ": position and direction must be finite (a direction not zero)");
    }
    if (!std::isfinite(light.range) || light.range < 0.0f || !std::isfinite(light.innerConeAngle) ||
        !std::isfinite(light.outerConeAngle)) {
        throw std::invalid_argument(name + ": range and cone angles must be finite, the range not negative");
    }
}

// Where a light's direct light can land: a ranged point or spot light's range box, else all of it.
scene::Bounds lightReach(const scene::Light& light, const scene::Bounds& scene) {
    if (light.type == scene::LightType::Directional || light.range <= 0.0f) {
        return scene;
    }
    return {light.position - glm::vec3(light.range), light.position + glm::vec3(light.range)};
}

} // namespace

FrameRendererSettings presetRendererSettings(GiTechnique technique, const Preset& preset,
                                             const scene::Scene& scene, uint32_t width, uint32_t height) {
    FrameRendererSettings settings;
    settings.technique = technique;
    settings.deferred = {.width = width,
                         .height = height,
                         .sunShadowSize = preset.sunShadowSize,
                         .pointShadowSize = preset.pointShadowSize,
                         .log = [](std::string_view) {}};
    if (technique == GiTechnique::Lumen) {
        settings.lumen = lumenPreset(preset, scene);
    }
    if (technique == GiTechnique::Ddgi) {
        settings.ddgi = ddgiPreset(preset, scene);
    }
    if (technique == GiTechnique::ShGrid) {
        settings.shGrid = shGridPreset(preset, scene);
    }
    return settings;
}

FrameRenderer::FrameRenderer(rhi::IDevice& device, const scene::Scene& scene, GpuScene& gpuScene,
                             FrameRendererSettings settings)
    : scene_(scene), gpuScene_(gpuScene), technique_(settings.technique), camera_(scene.camera),
      deferred_(device, scene, gpuScene, settings.deferred) {
    switch (technique_) {
    case GiTechnique::Lumen:
        gi_ =
            std::make_unique<LumenGi>(device, scene, gpuScene, deferred_.width(), deferred_.height(),
                                      settings.lumen ? *settings.lumen : lumenPreset(kDefaultPreset, scene));
        break;
    case GiTechnique::Ddgi:
        gi_ = std::make_unique<DdgiGi>(device, scene, gpuScene, deferred_.width(), deferred_.height(),
                                       settings.ddgi ? *settings.ddgi : ddgiPreset(kDefaultPreset, scene));
        break;
    case GiTechnique::ShGrid:
        gi_ = std::make_unique<ShGridGi>(device, scene, gpuScene, deferred_.width(), deferred_.height(),
                                         settings.shGrid ? *settings.shGrid
                                                         : shGridPreset(kDefaultPreset, scene));
        break;
    case GiTechnique::Direct:
        break;
    }
    for (const scene::Instance& instance : scene.instances) {
        transforms_.push_back(instance.transform);
    }
    worldBounds_ = sceneBounds();
    materialUsers_.resize(scene.materials.size());
    for (const scene::Material& material : scene.materials) {
        emissions_.push_back(material.emission);
    }
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        for (const scene::Submesh& submesh : scene.meshes.at(scene.instances[i].mesh).submeshes) {
            if (submesh.material < materialUsers_.size() &&
                (materialUsers_[submesh.material].empty() || materialUsers_[submesh.material].back() != i)) {
                materialUsers_[submesh.material].push_back(i);
            }
        }
    }
}

float FrameRenderer::indirectScale() const {
    return gi_ ? gi_->indirectScale() : 0.0f;
}

void FrameRenderer::setCamera(const scene::Camera& camera) {
    camera_ = camera;
    deferred_.setCamera(camera);
}

void FrameRenderer::cameraCut() {
    if (gi_) {
        gi_->resetHistory();
    }
}

void FrameRenderer::moveInstance(uint32_t instance, const glm::mat4& transform) {
    if (instance >= transforms_.size()) {
        throw std::out_of_range("moveInstance: instance " + std::to_string(instance) + " of " +
                                std::to_string(transforms_.size()));
    }
    const std::string name =
        "moveInstance: instance " + std::to_string(instance) + " '" + scene_.instances[instance].name + "'";
    const float det = glm::determinant(glm::mat3(transform));
    if (!finite(transform) || det == 0.0f || !std::isfinite(det)) {
        throw std::invalid_argument(name + ": the transform is not finite or is singular");
    }
    if ((det < 0.0f) != (glm::determinant(glm::mat3(scene_.instances[instance].transform)) < 0.0f)) {
        throw std::invalid_argument(name + ": the transform would flip the instance's winding (mirror it); "
                                           "load a scene with the mirrored instance instead");
    }
    pendingMoves_.emplace_back(instance, transform);
}

void FrameRenderer::setLights(std::vector<scene::Light> lights) {
    for (size_t i = 0; i < lights.size(); ++i) {
        validateLight(lights[i], i);
        lights[i].direction = glm::normalize(lights[i].direction);
    }
    if (lights.size() > LUMINA_CARD_LIGHT_MASK_BITS) {
        throw std::invalid_argument("setLights: " + std::to_string(lights.size()) + " lights, at most " +
                                    std::to_string(LUMINA_CARD_LIGHT_MASK_BITS));
    }
    pendingLights_ = std::move(lights);
}

void FrameRenderer::setEmission(uint32_t material, const glm::vec3& emission) {
    if (material >= emissions_.size()) {
        throw std::out_of_range("setEmission: material " + std::to_string(material) + " of " +
                                std::to_string(emissions_.size()));
    }
    if (!finite(emission) || glm::any(glm::lessThan(emission, glm::vec3(0.0f)))) {
        throw std::invalid_argument("setEmission: material " + std::to_string(material) + " '" +
                                    scene_.materials[material].name +
                                    "': emission must be finite and not negative");
    }
    if (emission != emissions_[material]) {
        emissions_[material] = emission;
        pendingMaterials_.push_back(material);
    }
}

void FrameRenderer::applyScene(const scene::Scene& scene) {
    if (scene.instances.size() != transforms_.size() || scene.materials.size() != emissions_.size()) {
        throw std::invalid_argument(
            "applyScene: '" + scene.name + "' has " + std::to_string(scene.instances.size()) +
            " instances and " + std::to_string(scene.materials.size()) + " materials, the renderer's scene " +
            std::to_string(transforms_.size()) + " and " + std::to_string(emissions_.size()));
    }
    for (uint32_t i = 0; i < transforms_.size(); ++i) {
        if (scene.instances[i].transform != transforms_[i]) {
            moveInstance(i, scene.instances[i].transform);
        }
    }
    const std::vector<scene::Light>& shown = pendingLights_ ? *pendingLights_ : deferred_.sceneLights();
    if (scene.lights != shown) {
        setLights(scene.lights);
    }
    for (uint32_t m = 0; m < emissions_.size(); ++m) {
        setEmission(m, scene.materials[m].emission);
    }
}

scene::Bounds FrameRenderer::instanceBounds(uint32_t instance, const glm::mat4& transform) const {
    return scene::transformBounds(scene_.meshes.at(scene_.instances[instance].mesh).bounds, transform);
}

scene::Bounds FrameRenderer::sceneBounds() const {
    scene::Bounds bounds;
    for (uint32_t i = 0; i < transforms_.size(); ++i) {
        bounds.extend(instanceBounds(i, transforms_[i]));
    }
    return bounds;
}

void FrameRenderer::applyPendingChanges(FrameContext& frame) {
    lastChanges_ = {};
    if (pendingLights_) {
        // Lights first: the cards of instances moved below get masks for the new lights.
        const std::vector<scene::Light>& before = deferred_.sceneLights();
        const std::vector<uint32_t> changed = scene::changedLights(before, *pendingLights_);
        lastChanges_.changedLights = uint32_t(changed.size());
        std::vector<scene::Bounds> reach;
        for (uint32_t i : changed) {
            if (i < before.size()) {
                reach.push_back(lightReach(before[i], worldBounds_));
            }
            if (i < pendingLights_->size()) {
                reach.push_back(lightReach((*pendingLights_)[i], worldBounds_));
            }
        }
        if (lastChanges_.changedLights > 0) {
            deferred_.setLights(*pendingLights_);
            if (gi_) {
                gi_->setLights(deferred_.sceneLights(), deferred_.lightsVersion(), reach);
            }
        }
        pendingLights_.reset();
    }
    if (!pendingMoves_.empty()) {
        std::vector<scene::Bounds> moved;
        for (const auto& [instance, transform] : pendingMoves_) {
            if (transform == transforms_[instance]) {
                continue;
            }
            const scene::Bounds before = instanceBounds(instance, transforms_[instance]);
            const scene::Bounds after = instanceBounds(instance, transform);
            transforms_[instance] = transform;
            scene::Instance placed = scene_.instances[instance];
            placed.transform = transform;
            gpuScene_.recordInstance(frame.commands(), instance, placed);
            if (gi_) {
                gi_->moveInstance(instance, transform, before, after, deferred_.sceneLights());
            }
            moved.push_back(before);
            moved.push_back(after);
            ++lastChanges_.movedInstances;
        }
        if (!moved.empty()) {
            worldBounds_ = sceneBounds();
            deferred_.geometryMoved(worldBounds_, std::move(moved));
        }
        pendingMoves_.clear();
    }
    if (!pendingMaterials_.empty()) {
        for (uint32_t material : pendingMaterials_) {
            scene::Material changed = scene_.materials[material];
            changed.emission = emissions_[material];
            gpuScene_.recordMaterial(frame.commands(), material, changed);
            if (gi_) {
                for (uint32_t instance : materialUsers_[material]) {
                    gi_->instanceMaterialChanged(instance, worldBounds_);
                }
            }
            ++lastChanges_.changedMaterials;
        }
        pendingMaterials_.clear();
    }
}

void FrameRenderer::render(FrameContext& frame) {
    // One list is the split with every part in it: the passes beside the raster come right after
    // the deferred lighting, where record() would record them, so the order is the same.
    render(SplitFrame{frame, frame, frame});
}

bool FrameRenderer::render(const SplitFrame& frame) {
    applyPendingChanges(frame.raster);
    if (!gi_) {
        deferred_.render(frame.raster);
        return false;
    }
    deferred_.recordLighting(frame.raster);
    const bool besideRaster = gi_->recordBesideRaster(frame.async, deferred_, camera_);
    gi_->record(frame.gather, deferred_, camera_);
    deferred_.setIndirect(gi_->indirect(), gi_->indirectScale());
    deferred_.recordComposite(frame.gather);
    return besideRaster;
}

} // namespace lumina::gi
