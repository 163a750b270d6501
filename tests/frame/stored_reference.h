#pragma once
// Lumen measured against the stored path-traced references of tests/frame/data (128 x 128, pixel
// centres; how they were made: frame_reference_accuracy_gpu_test.cpp): one scene at one preset
// rendered until converged, then 48 frames, as `lumina render` runs.
#include "rhi/rhi.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace lumina::test {

inline constexpr uint32_t kStoredReferenceSize = 128;

// A scene name here may carry a pose: "door@240" is `door` posed at frame 240 of its animation and
// held still (`lumina render --animation-frame 240`; `lumina reference` takes the same flag).

// tests/frame/data/<scene>_128x128.exr (<scene>_frame<F>_128x128.exr for "<scene>@F"), or the
// reference of the scene whose image `scene` shares: cornell_box_moving, held at its first pose, is
// cornell_box (the path tracer renders both to the same bits).
std::filesystem::path storedReferencePath(const std::string& scene);

// "door@240" as "door_frame240": a name for a test or a file.
std::string poseName(const std::string& scene);

struct StoredReferenceFigures {
    double lumenRelMse = 0.0;
    double directRelMse = 0.0;   // the direct-only image (no GI) against the same reference
    double indirectRelMse = 0.0; // lumen's final less direct against the reference less direct
    double meanRatio = 0.0;      // lumen's mean radiance (R, G, B) / the reference's
    uint32_t frames = 0;
    bool converged = false;       // the surface cache converged
    bool referenceSized = false;  // the stored reference is 128 x 128
    uint64_t nonFinitePixels = 0; // in lumen's image
};

// Renders `scene` (posed where it names a frame) at `preset`, measures it and prints the figures.
// Throws when the reference cannot be read.
StoredReferenceFigures measureAgainstStoredReference(rhi::IDevice& device, rhi::ShaderLibrary& shaders,
                                                     const std::string& scene, const std::string& preset);

} // namespace lumina::test
