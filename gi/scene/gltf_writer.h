#pragma once
// Writes a scene as glTF 2.0 text with its buffer embedded (a data: URI), and the scene file
// that goes with it: how the small built-in scenes under scenes/ are made. Lengths are
// written in scene units; point and spot intensities in candela through
// scene.units.metresPerUnit (units.h), so that loading the pair gives the scene back.
#include "gi/scene/scene.h"

#include <string>

namespace lumina::scene {

std::string writeGltf(const Scene& scene);

// The scene file for `scene` pointing at `gltfFileName` (beside it): units, sky, image size,
// technique, preset and description; camera and lights live in the glTF.
std::string writeSceneFile(const Scene& scene, const std::string& gltfFileName);

} // namespace lumina::scene
