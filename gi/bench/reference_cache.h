#pragma once
// Path-traced references for the bench, rendered once and kept on disk: the file name holds
// the scene, size and sample count, and a key over everything that changes the image (the
// scene's geometry, materials, lights, camera and sky; size, samples, seed, bounce limit), so
// an edited scene never reuses a stale reference.
#include "gi/core/pipeline_cache.h"
#include "gi/image/image.h"
#include "gi/scene/scene.h"
#include "rhi/device.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace lumina::gi {

struct ReferenceRequest {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t spp = 256;
    uint32_t seed = 0x5eed; // references never share a seed with the path tracer under test
    uint32_t maxBounces = 1024;
};

struct Reference {
    image::Image image; // R, G, B, variance.*, and the AOVs (albedo, normal, direct, indirect)
    std::filesystem::path path;
    bool reused = false;  // read from the cache, not rendered
    double seconds = 0.0; // to render or to read
};

// $LUMINA_CACHE_DIR/references and its fallbacks (gi/core/cache_dir.h).
std::filesystem::path defaultReferenceDirectory();

// Everything of the scene that the path tracer sees, hashed (FNV-1a 64).
uint64_t sceneDigest(const scene::Scene& scene);
uint64_t referenceKey(const scene::Scene& scene, const ReferenceRequest& request);
std::filesystem::path referencePath(const std::filesystem::path& directory, const scene::Scene& scene,
                                    const ReferenceRequest& request);

// Reads the cached reference, or renders it (reporting progress as "done/total spp") and
// writes it. A damaged cache file is rendered again.
Reference loadOrRenderReference(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                                const ReferenceRequest& request, const std::filesystem::path& directory,
                                const std::function<void(uint32_t done, uint32_t total)>& progress = {});

// R, G, B of a reference's `prefix`.R/G/B channels ("indirect", "direct"), as an image the
// metrics take.
image::Image rgbOf(const image::Image& image, const std::string& prefix);

} // namespace lumina::gi
