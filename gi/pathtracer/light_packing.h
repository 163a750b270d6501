#pragma once
// Scene lights in the GPU layout of shaders/common/lights_shared.h, the one light model of
// the path tracer and the real-time renderer (docs/conventions.md).
#include "gi/scene/scene.h"
#include "shaders/common/lights_shared.h"

#include <vector>

namespace lumina::gi {

// Strength = colour x intensity in scene units (units.h); the direction is normalised; spot
// cones become KHR_lights_punctual's scale and offset of cos(angle).
gpu::GpuLight packLight(const scene::Light& light);
std::vector<gpu::GpuLight> packLights(const std::vector<scene::Light>& lights);

} // namespace lumina::gi
