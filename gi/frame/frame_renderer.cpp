#include "gi/frame/frame_renderer.h"

#include <numbers>

namespace lumina::gi {

FrameRenderer::FrameRenderer(rhi::IDevice& device, const scene::Scene& scene, const GpuScene& gpuScene,
                             FrameRendererSettings settings)
    : technique_(settings.technique), camera_(scene.camera),
      deferred_(device, scene, gpuScene, settings.deferred) {
    if (technique_ == GiTechnique::Lumen) {
        const LumenSettings lumen = settings.lumen ? *settings.lumen : lumenPreset(kDefaultPreset, scene);
        lumen_ =
            std::make_unique<LumenGi>(device, scene, gpuScene, deferred_.width(), deferred_.height(), lumen);
    }
}

float FrameRenderer::indirectScale() const {
    // The probes gather irradiance E; a Lambertian surface of albedo a sends a x E / pi.
    return float(std::numbers::inv_pi);
}

void FrameRenderer::setCamera(const scene::Camera& camera) {
    camera_ = camera;
    deferred_.setCamera(camera);
}

void FrameRenderer::cameraCut() {
    if (lumen_) {
        lumen_->resetHistory();
    }
}

void FrameRenderer::render(FrameContext& frame) {
    if (!lumen_) {
        deferred_.render(frame);
        return;
    }
    deferred_.recordLighting(frame);
    lumen_->record(frame, deferred_, camera_);
    deferred_.setIndirect(lumen_->irradiance(), indirectScale());
    deferred_.recordComposite(frame);
}

} // namespace lumina::gi
