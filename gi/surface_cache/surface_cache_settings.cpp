#include "gi/surface_cache/surface_cache_settings.h"

#include "gi/surface_cache/tile_allocator.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lumina::surface_cache {

void validate(const SurfaceCacheSettings& s) {
    const auto fail = [](const std::string& what) {
        throw std::invalid_argument("SurfaceCacheSettings: " + what);
    };
    if (s.atlasSize == 0 || s.atlasSize % kTileSize != 0 || s.atlasSize / kTileSize > kMaxAtlasTilesPerSide) {
        fail("atlasSize " + std::to_string(s.atlasSize) + " must be a positive multiple of " +
             std::to_string(kTileSize) + " up to " + std::to_string(kTileSize * kMaxAtlasTilesPerSide));
    }
    if (!(s.texelsPerUnit > 0.0f) || !std::isfinite(s.texelsPerUnit)) {
        fail("texelsPerUnit " + std::to_string(s.texelsPerUnit) + " must be positive and finite");
    }
    if (s.maxCardTexels == 0) {
        fail("maxCardTexels must be at least 1");
    }
    if (s.maxLodLevel > 16) {
        fail("maxLodLevel " + std::to_string(s.maxLodLevel) + " must be at most 16");
    }
    if (!(s.atlasFill > 0.0f && s.atlasFill <= 1.0f)) {
        fail("atlasFill " + std::to_string(s.atlasFill) + " must be in (0, 1]");
    }
    if (!(s.lodHysteresis >= 1.0f) || !std::isfinite(s.lodHysteresis)) {
        fail("lodHysteresis " + std::to_string(s.lodHysteresis) + " must be at least 1 and finite");
    }
    if (s.lodChangesPerFrame == 0 || s.capturesPerFrame == 0) {
        fail("lodChangesPerFrame and capturesPerFrame must be at least 1");
    }
    if (!(s.paddingTexels > 0.0f) || !std::isfinite(s.paddingTexels)) {
        fail("paddingTexels " + std::to_string(s.paddingTexels) + " must be positive and finite");
    }
    if (!(s.minPaddingUnits >= 0.0f) || !std::isfinite(s.minPaddingUnits)) {
        fail("minPaddingUnits " + std::to_string(s.minPaddingUnits) + " must be non-negative and finite");
    }
    if (s.maxCardsPerAxis == 0) {
        fail("maxCardsPerAxis must be at least 1");
    }
    if (!(s.layerGap >= 0.0f) || !std::isfinite(s.layerGap)) {
        fail("layerGap " + std::to_string(s.layerGap) + " must be non-negative and finite");
    }
}

} // namespace lumina::surface_cache
