#include "gi/surface_cache/tile_owner_texture.h"

#include "shaders/surface_cache/surface_card_shared.h"

#include <stdexcept>
#include <string>

namespace lumina::surface_cache {

// Kernels test the lookup against LUMINA_NO_CARD; the table holds kNoOwner.
static_assert(kNoOwner == LUMINA_NO_CARD, "a free tile must read as no card on the GPU");

TileOwnerTexture::TileOwnerTexture(rhi::IDevice& device, const TileAllocator& allocator)
    : tilesX_(allocator.tilesX()), tilesY_(allocator.tilesY()) {
    texture_ = device.createTexture({.format = rhi::Format::R32_UINT,
                                     .width = tilesX_,
                                     .height = tilesY_,
                                     .usage = rhi::TextureUsage::Sampled,
                                     .debugName = "surface cache tile-to-card lookup"});
}

void TileOwnerTexture::recordUpload(rhi::ICommandList& commands, const TileAllocator& allocator) const {
    if (allocator.tilesX() != tilesX_ || allocator.tilesY() != tilesY_) {
        throw std::invalid_argument("tile-to-card lookup: the allocator has " +
                                    std::to_string(allocator.tilesX()) + "x" +
                                    std::to_string(allocator.tilesY()) + " tiles, the texture " +
                                    std::to_string(tilesX_) + "x" + std::to_string(tilesY_));
    }
    commands.writeTexture(*texture_, {}, allocator.ownerTable().data());
}

} // namespace lumina::surface_cache
