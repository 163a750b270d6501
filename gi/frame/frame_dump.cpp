#include "gi/frame/frame_dump.h"

#include "gi/deferred/buffer_readback.h"
#include "gi/frame/indirect_term.h"
#include "gi/image/exr.h"
#include "gi/image/png.h"
#include "gi/screen_probes/screen_probe_readback.h"
#include "gi/surface_cache/surface_cache_at_pixels.h"
#include "gi/surface_cache/surface_cache_dump.h"

#include <cctype>
#include <string>

namespace lumina::gi {

namespace {

// The cache's final lighting under each pixel (gi/surface_cache/surface_cache_at_pixels.h):
// compared with a reference, the cache's share of the frame's error.
std::filesystem::path dumpCacheAtPixels(rhi::IDevice& device, const FrameRenderer& renderer,
                                        const surface_cache::SurfaceCache& cache,
                                        const std::filesystem::path& directory) {
    const GBuffer& gbuffer = renderer.deferred().gbuffer();
    const surface_cache::CacheAtPixels atPixels = surface_cache::cacheAtPixels(
        readTextureImage(device, *gbuffer.position), readTextureImage(device, *gbuffer.normal),
        cache.readLayer(surface_cache::AtlasLayer::FinalLighting), cache.atlas().size(),
        cache.cards().cards());
    const std::filesystem::path path = directory / "surface_cache_at_pixels.exr";
    image::writeExr(path, atPixels.radiance);
    return path;
}

} // namespace

std::vector<std::filesystem::path> dumpFrameBuffers(rhi::IDevice& device, const FrameRenderer& renderer,
                                                    const std::filesystem::path& directory,
                                                    const image::DisplayOptions& display) {
    std::vector<std::filesystem::path> written =
        dumpDeferredBuffers(device, renderer.deferred(), directory, display);
    if (renderer.gi() == nullptr) {
        return written;
    }
    // The indirect term: the gathered irradiance E, and the radiance it adds, albedo x E / pi.
    image::Image irradiance = readTextureImage(device, *renderer.indirect());
    irradiance.removeChannel("A");
    written.push_back(directory / "indirect_irradiance.exr");
    image::writeExr(written.back(), irradiance);
    const image::Image indirect =
        indirectRadiance(irradiance, readTextureImage(device, *renderer.deferred().gbuffer().albedo),
                         renderer.indirectScale());
    written.push_back(directory / "indirect.exr");
    image::writeExr(written.back(), indirect);
    written.push_back(directory / "indirect.png");
    image::writePng(written.back(), indirect, display);

    // Every texture the technique exposes to the debug views, by its name.
    for (const GiDebugTexture& debug : renderer.gi()->debugTextures()) {
        std::string file;
        for (char c : debug.name) {
            file += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        }
        written.push_back(directory / (file + ".exr"));
        image::writeExr(written.back(), readTextureImage(device, *debug.texture));
    }
    if (const LumenGi* lumen = renderer.lumen()) {
        for (auto& path :
             surface_cache::dumpSurfaceCache(device, lumen->surfaceCache(), directory, display)) {
            written.push_back(std::move(path));
        }
        written.push_back(dumpCacheAtPixels(device, renderer, lumen->surfaceCache(), directory));
        for (auto& path : dumpScreenProbeBuffers(device, lumen->screenProbes(), directory)) {
            written.push_back(std::move(path));
        }
    }
    if (const DdgiGi* ddgi = renderer.ddgi()) {
        for (auto& path : surface_cache::dumpSurfaceCache(device, ddgi->surfaceCache(), directory, display)) {
            written.push_back(std::move(path));
        }
        written.push_back(dumpCacheAtPixels(device, renderer, ddgi->surfaceCache(), directory));
    }
    return written;
}

} // namespace lumina::gi
