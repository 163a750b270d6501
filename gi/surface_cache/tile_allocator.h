#pragma once
// The surface-cache atlas allocator: rectangles of whole tiles (kTileSize texels a side), handed out and
// taken back as cards come and go.
//
// A quadtree buddy system over the tile grid. Free space is kept as aligned power-of-two
// square blocks (side 2^k tiles, origin a multiple of 2^k), one free list per level:
//   - allocate(w, h) pops a block of the smallest level that holds max(w, h), splitting a larger
//     one when that level is empty (at most `levels` splits: constant for a given atlas), keeps
//     the w x h rectangle at the block's origin and gives the rest of the block straight back
//     as smaller aligned blocks. A single tile from a non-empty level-0 list is one pop.
//   - release(rect) gives the rectangle back as its aligned blocks; a block whose three
//     siblings are free merges with them into their parent, and so on up. Merging is the
//     fragmentation recovery that needs no moves: once everything is released the atlas is
//     one block (or, for a non-power-of-two atlas, its maximal aligned blocks) again.
//   - defragment() is the recovery that does move: it re-places every live rectangle, largest
//     first, and reports which ones moved (their cards must be captured again).
// Removal of an arbitrary free block (needed to merge) is O(1) through a per-level slot table.
//
// The allocator also keeps which owner (a card index) holds each tile: the tile-to-card lookup
// of the direct-light pass is built from it, and it lets release() refuse a rectangle that is
// not exactly one live allocation.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lumina::surface_cache {

// Texels per tile side: the smallest card. Small enough that a city's thousands of distant cards
// each fit in one (a 2048 atlas holds 16384), large enough that a tile is a whole thread group of
// the atlas passes (256 texels) and holds 4x4 radiosity probes.
inline constexpr uint32_t kTileSize = 16;
inline constexpr uint32_t kNoOwner = 0xFFFFFFFFu;        // a free tile's owner
inline constexpr uint32_t kMaxAtlasTilesPerSide = 1024u; // 65536 texels: beyond any GPU's limit

// A rectangle of tiles: origin and size in tiles.
struct TileRect {
    uint32_t x = 0;
    uint32_t y = 0;
    uint32_t width = 0;
    uint32_t height = 0;

    uint32_t area() const { return width * height; }
    bool operator==(const TileRect&) const = default;
};

std::string toString(const TileRect& rect);

struct TileRelocation {
    uint32_t owner = kNoOwner;
    TileRect from;
    TileRect to;
};

class TileAllocator {
public:
    // An atlas of tilesX x tilesY tiles (each at least 1, at most kMaxAtlasTilesPerSide).
    TileAllocator(uint32_t tilesX, uint32_t tilesY);

    // A free width x height rectangle for `owner`, or nothing when no free block is large enough.
    std::optional<TileRect> tryAllocate(uint32_t width, uint32_t height, uint32_t owner);
    // As tryAllocate, but throws std::runtime_error naming the request and the free space.
    TileRect allocate(uint32_t width, uint32_t height, uint32_t owner);
    // Gives back a rectangle returned by allocate (throws std::invalid_argument otherwise).
    void release(const TileRect& rect);
    // Re-places every live rectangle, largest first; returns the ones that moved. When even the
    // repacked layout would not hold them all (it always does for power-of-two squares in a power-of-two
    // square atlas), nothing moves and the result is empty.
    std::vector<TileRelocation> defragment();

    uint32_t tilesX() const { return tilesX_; }
    uint32_t tilesY() const { return tilesY_; }
    uint32_t freeTiles() const { return freeTiles_; }
    uint32_t usedTiles() const { return tilesX_ * tilesY_ - freeTiles_; }
    // Side in tiles of the largest free block: no rectangle wider or taller can be allocated.
    uint32_t largestFreeBlock() const;
    uint32_t owner(uint32_t tileX, uint32_t tileY) const;
    // Every tile's owner, row-major (tilesX per row), kNoOwner where free: the contents of the
    // tile-to-card lookup that lets an atlas pass find a texel's card with one load.
    const std::vector<uint32_t>& ownerTable() const { return owners_; }
    // Free blocks per level (index k: blocks of side 2^k), for tests and diagnostics.
    std::vector<uint32_t> freeBlockCounts() const;

private:
    struct Level {
        uint32_t side = 0;              // blocks per row at this level
        std::vector<uint32_t> freeList; // block indices (y * side + x)
        std::vector<uint32_t> slot;     // per block: position in freeList, or kNotFree
    };
    struct Live {
        TileRect rect;
        uint32_t owner = kNoOwner;
    };

    void reset();
    bool isFree(uint32_t level, uint32_t bx, uint32_t by) const;
    void pushFree(uint32_t level, uint32_t bx, uint32_t by);
    void removeFree(uint32_t level, uint32_t bx, uint32_t by);
    uint32_t popFree(uint32_t level);
    // Frees an aligned block, merging it with its siblings while all four are free.
    void releaseBlock(uint32_t level, uint32_t bx, uint32_t by);
    // Frees the part of block (level, bx, by) that lies inside `region` and outside `keep`.
    void releaseRegion(uint32_t level, uint32_t bx, uint32_t by, const TileRect& region, const TileRect* keep,
                       bool merge);
    void setOwner(const TileRect& rect, uint32_t owner);

    uint32_t tilesX_ = 0;
    uint32_t tilesY_ = 0;
    uint32_t topLevel_ = 0; // the root block has side 2^topLevel_ >= max(tilesX, tilesY)
    uint32_t freeTiles_ = 0;
    std::vector<Level> levels_;
    std::vector<uint32_t> owners_;    // per tile, row-major
    std::vector<Live> live_;          // live allocations, indexed by liveIndex_ of their origin tile
    std::vector<uint32_t> liveIndex_; // per tile: index into live_ for an allocation's origin tile
};

} // namespace lumina::surface_cache
