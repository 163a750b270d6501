#pragma once
// A list of atlas tiles on the GPU (StructuredBuffer<uint>, row-major tile indices) that an
// atlas pass walks with one thread per texel or probe of each listed tile, so a pass touches
// only the tiles that need it (cards, or the radiosity budget's pick) and never the free atlas.
#include "rhi/rhi.h"

#include <cstdint>
#include <span>
#include <string>

namespace lumina::surface_cache {

class AtlasTileList {
public:
    // Room for every tile of an atlas of `atlasSize` texels per side.
    AtlasTileList(rhi::IDevice& device, uint32_t atlasSize, std::string name);

    // Records the upload of `tiles` (each below the atlas's tile count; throws
    // std::out_of_range naming the first that is not).
    void recordUpload(rhi::ICommandList& commands, std::span<const uint32_t> tiles);

    // The thread counts of a dispatch with `itemsPerTile` threads a listed tile, numbered flat
    // and folded into rows of LUMINA_TILE_LIST_ROW_THREADS (tileListItem in HLSL).
    uint32_t threadsX(uint32_t itemsPerTile) const;
    uint32_t threadsY(uint32_t itemsPerTile) const;

    const rhi::BufferHandle& buffer() const { return buffer_; }
    uint32_t count() const { return count_; }
    uint32_t tilesPerRow() const { return tilesPerRow_; }

private:
    rhi::BufferHandle buffer_;
    std::string name_;
    uint32_t tilesPerRow_ = 0;
    uint32_t count_ = 0;
};

} // namespace lumina::surface_cache
