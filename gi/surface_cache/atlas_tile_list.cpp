#include "gi/surface_cache/atlas_tile_list.h"

#include "gi/surface_cache/tile_allocator.h"
#include "shaders/surface_cache/surface_cache_lighting_shared.h"

#include <algorithm>
#include <stdexcept>

namespace lumina::surface_cache {

AtlasTileList::AtlasTileList(rhi::IDevice& device, uint32_t atlasSize, std::string name)
    : name_(std::move(name)), tilesPerRow_(atlasSize / kTileSize) {
    const uint64_t tiles = uint64_t(tilesPerRow_) * tilesPerRow_;
    buffer_ = device.createBuffer({.size = tiles * sizeof(uint32_t),
                                   .structStride = sizeof(uint32_t),
                                   .usage = rhi::BufferUsage::Structured,
                                   .debugName = name_});
}

void AtlasTileList::recordUpload(rhi::ICommandList& commands, std::span<const uint32_t> tiles) {
    const uint32_t atlasTiles = tilesPerRow_ * tilesPerRow_;
    for (uint32_t tile : tiles) {
        if (tile >= atlasTiles) {
            throw std::out_of_range(name_ + ": tile " + std::to_string(tile) + " of an atlas of " +
                                    std::to_string(atlasTiles) + " tiles");
        }
    }
    if (tiles.size() > atlasTiles) {
        throw std::out_of_range(name_ + ": " + std::to_string(tiles.size()) +
                                " tiles listed, the atlas has " + std::to_string(atlasTiles));
    }
    count_ = uint32_t(tiles.size());
    if (!tiles.empty()) {
        commands.writeBuffer(*buffer_, tiles.data(), tiles.size_bytes());
    }
}

uint32_t AtlasTileList::threadsX(uint32_t itemsPerTile) const {
    return uint32_t(std::min<uint64_t>(uint64_t(count_) * itemsPerTile, LUMINA_TILE_LIST_ROW_THREADS));
}

uint32_t AtlasTileList::threadsY(uint32_t itemsPerTile) const {
    const uint64_t threads = uint64_t(count_) * itemsPerTile;
    return uint32_t((threads + LUMINA_TILE_LIST_ROW_THREADS - 1) / LUMINA_TILE_LIST_ROW_THREADS);
}

} // namespace lumina::surface_cache
