// The atlas tile allocator under random allocate/release sequences, checked against a reference
// occupancy grid: no overlap, every tile accounted for, everything released reusable, and
// recovery from fragmentation both by merging and by defragment().
#include "gi/surface_cache/tile_allocator.h"

#include <gtest/gtest.h>
#include <map>
#include <random>

namespace lumina::surface_cache {
namespace {

// Checks every live rectangle against the allocator's owner map and free count.
void expectConsistent(const TileAllocator& atlas, const std::map<uint32_t, TileRect>& live) {
    std::vector<uint32_t> reference(size_t(atlas.tilesX()) * atlas.tilesY(), kNoOwner);
    uint32_t used = 0;
    for (const auto& [owner, rect] : live) {
        ASSERT_LE(rect.x + rect.width, atlas.tilesX()) << toString(rect);
        ASSERT_LE(rect.y + rect.height, atlas.tilesY()) << toString(rect);
        for (uint32_t y = rect.y; y < rect.y + rect.height; ++y) {
            for (uint32_t x = rect.x; x < rect.x + rect.width; ++x) {
                uint32_t& tile = reference[size_t(y) * atlas.tilesX() + x];
                ASSERT_EQ(tile, kNoOwner)
                    << "owners " << tile << " and " << owner << " overlap at " << x << ", " << y;
                tile = owner;
            }
        }
        used += rect.area();
    }
    ASSERT_EQ(atlas.usedTiles(), used);
    for (uint32_t y = 0; y < atlas.tilesY(); ++y) {
        for (uint32_t x = 0; x < atlas.tilesX(); ++x) {
            ASSERT_EQ(atlas.owner(x, y), reference[size_t(y) * atlas.tilesX() + x]) << x << ", " << y;
        }
    }
    // The free blocks cover exactly the free tiles.
    uint64_t freeArea = 0;
    const std::vector<uint32_t> blocks = atlas.freeBlockCounts();
    for (size_t level = 0; level < blocks.size(); ++level) {
        freeArea += uint64_t(blocks[level]) << (2 * level);
    }
    ASSERT_EQ(freeArea, atlas.freeTiles());
}

// After everything is released, the atlas is whole: the same free blocks as a fresh one (a
// power-of-two atlas: one block of all of it), and a request for its largest block succeeds.
void expectWholeAgain(TileAllocator& atlas) {
    ASSERT_EQ(atlas.freeTiles(), atlas.tilesX() * atlas.tilesY());
    EXPECT_EQ(atlas.freeBlockCounts(), TileAllocator(atlas.tilesX(), atlas.tilesY()).freeBlockCounts());
    const uint32_t side = atlas.largestFreeBlock();
    const TileRect block = atlas.allocate(side, side, 1);
    EXPECT_EQ(block.area(), side * side);
    atlas.release(block);
    const bool powerOfTwoSquare = atlas.tilesX() == atlas.tilesY() && side == atlas.tilesX();
    if (powerOfTwoSquare) {
        const TileRect all = atlas.allocate(atlas.tilesX(), atlas.tilesY(), 1);
        EXPECT_EQ(all, (TileRect{0, 0, atlas.tilesX(), atlas.tilesY()}));
        atlas.release(all);
    }
}

class SurfaceCacheTilesRandom : public ::testing::TestWithParam<std::pair<uint32_t, uint32_t>> {};

TEST_P(SurfaceCacheTilesRandom, NoOverlapAndEverythingFreedIsReusable) {
    const auto [tilesX, tilesY] = GetParam();
    TileAllocator atlas(tilesX, tilesY);
    std::mt19937 rng(tilesX * 131 + tilesY);
    std::map<uint32_t, TileRect> live;
    uint32_t nextOwner = 0;
    uint32_t failures = 0;
    for (int step = 0; step < 3000; ++step) {
        const bool allocate = live.empty() || std::uniform_int_distribution<int>(0, 99)(rng) < 55;
        if (allocate) {
            // Mostly small cards, a few large ones, as a scene's cards are.
            const uint32_t cap = std::uniform_int_distribution<int>(0, 9)(rng) == 0 ? 20u : 4u;
            const uint32_t w = std::uniform_int_distribution<uint32_t>(1, cap)(rng);
            const uint32_t h = std::uniform_int_distribution<uint32_t>(1, cap)(rng);
            if (std::optional<TileRect> rect = atlas.tryAllocate(w, h, nextOwner)) {
                EXPECT_EQ(rect->width, w);
                EXPECT_EQ(rect->height, h);
                live[nextOwner++] = *rect;
            } else {
                ++failures;
                // A failure must be real: no free block of the needed level exists.
                EXPECT_LT(atlas.largestFreeBlock(), std::max(w, h)) << w << "x" << h;
            }
        } else {
            auto it = live.begin();
            std::advance(it, std::uniform_int_distribution<size_t>(0, live.size() - 1)(rng));
            atlas.release(it->second);
            live.erase(it);
        }
        if (step % 50 == 0) {
            expectConsistent(atlas, live);
        }
    }
    expectConsistent(atlas, live);
    for (const auto& [owner, rect] : live) {
        atlas.release(rect);
    }
    live.clear();
    expectConsistent(atlas, live);
    expectWholeAgain(atlas);
}

INSTANTIATE_TEST_SUITE_P(Sizes, SurfaceCacheTilesRandom,
                         ::testing::Values(std::pair{64u, 64u}, std::pair{48u, 40u}, std::pair{16u, 16u},
                                           std::pair{7u, 3u}, std::pair{1u, 1u}));

TEST(SurfaceCacheTiles, SingleTilesFillTheAtlasAndAreReusedAfterRelease) {
    TileAllocator atlas(64, 64);
    std::vector<TileRect> tiles;
    for (uint32_t i = 0; i < 64 * 64; ++i) {
        tiles.push_back(atlas.allocate(1, 1, i));
    }
    EXPECT_EQ(atlas.freeTiles(), 0u);
    EXPECT_FALSE(atlas.tryAllocate(1, 1, 99999).has_value());
    // A released tile is the next one handed out.
    atlas.release(tiles[1234]);
    EXPECT_EQ(atlas.allocate(1, 1, 5000), tiles[1234]);
    atlas.release(tiles[1234]);
    for (uint32_t i = 0; i < tiles.size(); ++i) {
        if (i != 1234) {
            atlas.release(tiles[i]);
        }
    }
    // Merging brought back one 64x64 block.
    const std::vector<uint32_t> blocks = atlas.freeBlockCounts();
    for (size_t level = 0; level + 1 < blocks.size(); ++level) {
        EXPECT_EQ(blocks[level], 0u) << "level " << level;
    }
    EXPECT_EQ(blocks.back(), 1u);
    expectWholeAgain(atlas);
}

TEST(SurfaceCacheTiles, RecoversFromFragmentationByMergingAndByDefragment) {
    TileAllocator atlas(64, 64);
    std::map<uint32_t, TileRect> live;
    for (uint32_t i = 0; i < 64 * 64; ++i) {
        live[i] = atlas.allocate(1, 1, i);
    }
    // A checkerboard of holes: half the atlas free, yet no 2x2 rectangle.
    for (auto it = live.begin(); it != live.end();) {
        if ((it->second.x + it->second.y) % 2 == 0) {
            atlas.release(it->second);
            it = live.erase(it);
        } else {
            ++it;
        }
    }
    expectConsistent(atlas, live);
    EXPECT_EQ(atlas.freeTiles(), 2048u);
    EXPECT_EQ(atlas.largestFreeBlock(), 1u);
    EXPECT_FALSE(atlas.tryAllocate(2, 2, 100000).has_value());

    // Merging: releasing the rest of the top-left 8x8 block makes it whole again.
    for (auto it = live.begin(); it != live.end();) {
        if (it->second.x < 8 && it->second.y < 8) {
            atlas.release(it->second);
            it = live.erase(it);
        } else {
            ++it;
        }
    }
    EXPECT_EQ(atlas.largestFreeBlock(), 8u);
    const TileRect merged = atlas.allocate(8, 8, 100000);
    EXPECT_EQ(merged, (TileRect{0, 0, 8, 8}));
    live[100000] = merged;
    expectConsistent(atlas, live);

    // Defragment: the scattered single tiles are packed, and the free half comes back whole.
    const uint32_t freeBefore = atlas.freeTiles();
    const std::vector<TileRelocation> moved = atlas.defragment();
    EXPECT_FALSE(moved.empty());
    for (const TileRelocation& m : moved) {
        ASSERT_TRUE(live.count(m.owner));
        EXPECT_EQ(live[m.owner], m.from);
        EXPECT_EQ(m.to.width, m.from.width);
        EXPECT_EQ(m.to.height, m.from.height);
        live[m.owner] = m.to;
    }
    expectConsistent(atlas, live);
    EXPECT_EQ(atlas.freeTiles(), freeBefore);
    EXPECT_GE(atlas.largestFreeBlock(), 16u);
    live[200000] = atlas.allocate(16, 16, 200000);
    expectConsistent(atlas, live);
}

TEST(SurfaceCacheTiles, RectanglesKeepTheirSizeAndTheRestOfTheirBlockStaysUsable) {
    TileAllocator atlas(16, 16);
    const TileRect a = atlas.allocate(9, 3, 1); // takes a 16x16 block, gives back the rest
    EXPECT_EQ(a.area(), 27u);
    EXPECT_EQ(atlas.freeTiles(), 256u - 27u);
    // The rest holds 256 - 27 single tiles.
    std::vector<TileRect> rest;
    while (std::optional<TileRect> t = atlas.tryAllocate(1, 1, uint32_t(rest.size() + 2))) {
        rest.push_back(*t);
    }
    EXPECT_EQ(rest.size(), 256u - 27u);
}

TEST(SurfaceCacheTiles, BadInputThrowsNamingTheValue) {
    EXPECT_THROW(TileAllocator(0, 4), std::invalid_argument);
    EXPECT_THROW(TileAllocator(4, kMaxAtlasTilesPerSide + 1), std::invalid_argument);
    TileAllocator atlas(4, 4);
    EXPECT_THROW(atlas.tryAllocate(0, 1, 1), std::invalid_argument);
    EXPECT_THROW(atlas.tryAllocate(1, 1, kNoOwner), std::invalid_argument);
    EXPECT_FALSE(atlas.tryAllocate(5, 1, 1).has_value());
    const TileRect r = atlas.allocate(2, 2, 1);
    EXPECT_THROW(atlas.release(TileRect{r.x, r.y, 1, 1}), std::invalid_argument); // not the allocation
    EXPECT_THROW(atlas.release(TileRect{3, 3, 1, 1}), std::invalid_argument);     // free
    atlas.release(r);
    EXPECT_THROW(atlas.release(r), std::invalid_argument); // twice
    atlas.allocate(4, 4, 1);
    try {
        atlas.allocate(1, 2, 7);
        FAIL() << "a full atlas allocated";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("atlas full"), std::string::npos) << message;
        EXPECT_NE(message.find("1x2 tiles"), std::string::npos) << message;
        EXPECT_NE(message.find("0 of 16 tiles free"), std::string::npos) << message;
    }
}

} // namespace
} // namespace lumina::surface_cache
