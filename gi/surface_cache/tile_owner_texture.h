#pragma once
// The tile-to-card lookup on the GPU: an R32_UINT texture of one texel per atlas tile (64x64 at
// the default 4096^2 atlas) holding the card that owns the tile (TileAllocator::ownerTable,
// LUMINA_NO_CARD where free), so an atlas pass finds a texel's card with one Load instead of
// scanning cards.
#include "gi/surface_cache/tile_allocator.h"
#include "rhi/rhi.h"

namespace lumina::surface_cache {

class TileOwnerTexture {
public:
    TileOwnerTexture(rhi::IDevice& device, const TileAllocator& allocator);

    // Records the upload of the allocator's owner table (after cards were placed or moved).
    // Throws std::invalid_argument when the allocator's grid is not this texture's size.
    void recordUpload(rhi::ICommandList& commands, const TileAllocator& allocator) const;

    const rhi::TextureHandle& texture() const { return texture_; }

private:
    uint32_t tilesX_ = 0;
    uint32_t tilesY_ = 0;
    rhi::TextureHandle texture_;
};

} // namespace lumina::surface_cache
