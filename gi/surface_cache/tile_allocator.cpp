#include "gi/surface_cache/tile_allocator.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace lumina::surface_cache {
namespace {

constexpr uint32_t kNotFree = 0xFFFFFFFFu;

uint32_t ceilLog2(uint32_t v) {
    return v <= 1 ? 0u : uint32_t(std::bit_width(v - 1));
}

bool overlaps(const TileRect& a, const TileRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

bool containsRect(const TileRect& outer, const TileRect& inner) {
    return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.width <= outer.x + outer.width &&
           inner.y + inner.height <= outer.y + outer.height;
}

} // namespace

std::string toString(const TileRect& rect) {
    return std::to_string(rect.width) + "x" + std::to_string(rect.height) + " tiles at (" +
           std::to_string(rect.x) + ", " + std::to_string(rect.y) + ")";
}

TileAllocator::TileAllocator(uint32_t tilesX, uint32_t tilesY) : tilesX_(tilesX), tilesY_(tilesY) {
    if (tilesX == 0 || tilesY == 0 || tilesX > kMaxAtlasTilesPerSide || tilesY > kMaxAtlasTilesPerSide) {
        throw std::invalid_argument("TileAllocator: atlas of " + std::to_string(tilesX) + "x" +
                                    std::to_string(tilesY) + " tiles; each side must be 1.." +
                                    std::to_string(kMaxAtlasTilesPerSide));
    }
    topLevel_ = ceilLog2(std::max(tilesX, tilesY));
    levels_.resize(topLevel_ + 1);
    for (uint32_t level = 0; level <= topLevel_; ++level) {
        levels_[level].side = 1u << (topLevel_ - level);
    }
    reset();
}

void TileAllocator::reset() {
    for (Level& level : levels_) {
        level.freeList.clear();
        level.slot.assign(size_t(level.side) * level.side, kNotFree);
    }
    owners_.assign(size_t(tilesX_) * tilesY_, kNoOwner);
    liveIndex_.assign(size_t(tilesX_) * tilesY_, kNotFree);
    live_.clear();
    freeTiles_ = tilesX_ * tilesY_;
    // A non-power-of-two atlas starts as the maximal aligned blocks inside it; blocks that
    // would cross its edge are never free, so they never merge past it.
    releaseRegion(topLevel_, 0, 0, TileRect{0, 0, tilesX_, tilesY_}, nullptr, false);
}

bool TileAllocator::isFree(uint32_t level, uint32_t bx, uint32_t by) const {
    const Level& l = levels_[level];
    return l.slot[size_t(by) * l.side + bx] != kNotFree;
}

void TileAllocator::pushFree(uint32_t level, uint32_t bx, uint32_t by) {
    Level& l = levels_[level];
    const uint32_t block = by * l.side + bx;
    l.slot[block] = uint32_t(l.freeList.size());
    l.freeList.push_back(block);
}

void TileAllocator::removeFree(uint32_t level, uint32_t bx, uint32_t by) {
    Level& l = levels_[level];
    const uint32_t block = by * l.side + bx;
    const uint32_t position = l.slot[block];
    const uint32_t last = l.freeList.back();
    l.freeList[position] = last;
    l.slot[last] = position;
    l.freeList.pop_back();
    l.slot[block] = kNotFree;
}

uint32_t TileAllocator::popFree(uint32_t level) {
    Level& l = levels_[level];
    const uint32_t block = l.freeList.back();
    l.freeList.pop_back();
    l.slot[block] = kNotFree;
    return block;
}

void TileAllocator::releaseBlock(uint32_t level, uint32_t bx, uint32_t by) {
    while (level < topLevel_) {
        const uint32_t px = bx & ~1u, py = by & ~1u;
        bool siblingsFree = true;
        for (uint32_t i = 0; i < 4 && siblingsFree; ++i) {
            const uint32_t sx = px + (i & 1u), sy = py + (i >> 1);
            siblingsFree = (sx == bx && sy == by) || isFree(level, sx, sy);
        }
        if (!siblingsFree) {
            break;
        }
        for (uint32_t i = 0; i < 4; ++i) {
            const uint32_t sx = px + (i & 1u), sy = py + (i >> 1);
            if (sx != bx || sy != by) {
                removeFree(level, sx, sy);
            }
        }
        ++level;
        bx >>= 1;
        by >>= 1;
    }
    pushFree(level, bx, by);
}

void TileAllocator::releaseRegion(uint32_t level, uint32_t bx, uint32_t by, const TileRect& region,
                                  const TileRect* keep, bool merge) {
    const uint32_t side = 1u << level;
    const TileRect block{bx << level, by << level, side, side};
    if (!overlaps(block, region)) {
        return;
    }
    if (containsRect(region, block) && (keep == nullptr || !overlaps(block, *keep))) {
        if (merge) {
            releaseBlock(level, bx, by);
        } else {
            pushFree(level, bx, by);
        }
        return;
    }
    if (level == 0) {
        return; // one tile, outside the region or kept
    }
    for (uint32_t i = 0; i < 4; ++i) {
        releaseRegion(level - 1, 2 * bx + (i & 1u), 2 * by + (i >> 1), region, keep, merge);
    }
}

void TileAllocator::setOwner(const TileRect& rect, uint32_t owner) {
    for (uint32_t y = rect.y; y < rect.y + rect.height; ++y) {
        std::fill_n(owners_.begin() + size_t(y) * tilesX_ + rect.x, rect.width, owner);
    }
}

std::optional<TileRect> TileAllocator::tryAllocate(uint32_t width, uint32_t height, uint32_t owner) {
    if (width == 0 || height == 0) {
        throw std::invalid_argument("TileAllocator: cannot allocate " + std::to_string(width) + "x" +
                                    std::to_string(height) + " tiles");
    }
    if (owner == kNoOwner) {
        throw std::invalid_argument("TileAllocator: owner 0xFFFFFFFF is reserved for free tiles");
    }
    if (width > tilesX_ || height > tilesY_) {
        return std::nullopt;
    }
    const uint32_t want = ceilLog2(std::max(width, height));
    uint32_t level = want;
    while (level <= topLevel_ && levels_[level].freeList.empty()) {
        ++level;
    }
    if (level > topLevel_) {
        return std::nullopt;
    }
    const uint32_t block = popFree(level);
    uint32_t bx = block % levels_[level].side, by = block / levels_[level].side;
    // Split down to the wanted level, keeping the first quadrant each time.
    while (level > want) {
        --level;
        bx *= 2;
        by *= 2;
        pushFree(level, bx + 1, by);
        pushFree(level, bx, by + 1);
        pushFree(level, bx + 1, by + 1);
    }
    const uint32_t side = 1u << want;
    const TileRect rect{bx << want, by << want, width, height};
    // The rest of the block goes straight back; none of it can merge, since its parent holds `rect`.
    releaseRegion(want, bx, by, TileRect{rect.x, rect.y, side, side}, &rect, false);
    freeTiles_ -= rect.area();
    setOwner(rect, owner);
    liveIndex_[size_t(rect.y) * tilesX_ + rect.x] = uint32_t(live_.size());
    live_.push_back({rect, owner});
    return rect;
}

TileRect TileAllocator::allocate(uint32_t width, uint32_t height, uint32_t owner) {
    if (std::optional<TileRect> rect = tryAllocate(width, height, owner)) {
        return *rect;
    }
    throw std::runtime_error("surface cache atlas full: owner " + std::to_string(owner) + " needs " +
                             std::to_string(width) + "x" + std::to_string(height) + " tiles; " +
                             std::to_string(freeTiles_) + " of " + std::to_string(tilesX_ * tilesY_) +
                             " tiles free, largest free block " + std::to_string(largestFreeBlock()) + "x" +
                             std::to_string(largestFreeBlock()));
}

void TileAllocator::release(const TileRect& rect) {
    const bool inside = rect.width > 0 && rect.height > 0 && rect.x < tilesX_ && rect.y < tilesY_;
    const uint32_t index = inside ? liveIndex_[size_t(rect.y) * tilesX_ + rect.x] : kNotFree;
    if (index == kNotFree || !(live_[index].rect == rect)) {
        throw std::invalid_argument("TileAllocator::release: " + toString(rect) +
                                    " is not a live allocation");
    }
    setOwner(rect, kNoOwner);
    liveIndex_[size_t(rect.y) * tilesX_ + rect.x] = kNotFree;
    if (index + 1 != live_.size()) {
        live_[index] = live_.back();
        liveIndex_[size_t(live_[index].rect.y) * tilesX_ + live_[index].rect.x] = index;
    }
    live_.pop_back();
    freeTiles_ += rect.area();
    releaseRegion(topLevel_, 0, 0, rect, nullptr, true);
}

std::vector<TileRelocation> TileAllocator::defragment() {
    std::vector<Live> order = live_;
    // Largest block level first (a buddy system packs descending power-of-two sizes without
    // gaps), then larger area, then owner so that the layout does not depend on history.
    std::sort(order.begin(), order.end(), [](const Live& a, const Live& b) {
        const uint32_t la = ceilLog2(std::max(a.rect.width, a.rect.height));
        const uint32_t lb = ceilLog2(std::max(b.rect.width, b.rect.height));
        if (la != lb) {
            return la > lb;
        }
        if (a.rect.area() != b.rect.area()) {
            return a.rect.area() > b.rect.area();
        }
        return a.owner < b.owner;
    });
    TileAllocator backup = *this;
    reset();
    std::vector<TileRelocation> moved;
    for (const Live& entry : order) {
        const std::optional<TileRect> rect = tryAllocate(entry.rect.width, entry.rect.height, entry.owner);
        if (!rect) {
            *this = std::move(backup);
            return {};
        }
        if (!(*rect == entry.rect)) {
            moved.push_back({entry.owner, entry.rect, *rect});
        }
    }
    return moved;
}

uint32_t TileAllocator::largestFreeBlock() const {
    for (uint32_t level = topLevel_ + 1; level-- > 0;) {
        if (!levels_[level].freeList.empty()) {
            return 1u << level;
        }
    }
    return 0;
}

uint32_t TileAllocator::owner(uint32_t tileX, uint32_t tileY) const {
    if (tileX >= tilesX_ || tileY >= tilesY_) {
        throw std::out_of_range("TileAllocator::owner: tile (" + std::to_string(tileX) + ", " +
                                std::to_string(tileY) + ") outside the " + std::to_string(tilesX_) + "x" +
                                std::to_string(tilesY_) + " atlas");
    }
    return owners_[size_t(tileY) * tilesX_ + tileX];
}

std::vector<uint32_t> TileAllocator::freeBlockCounts() const {
    std::vector<uint32_t> counts;
    for (const Level& level : levels_) {
        counts.push_back(uint32_t(level.freeList.size()));
    }
    return counts;
}

} // namespace lumina::surface_cache
