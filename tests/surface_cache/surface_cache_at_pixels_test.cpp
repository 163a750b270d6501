// cacheAtPixels (surface_cache_at_pixels.h): the cache under a pixel is read from the owning card's
// own texels, never from the card beside it in the atlas.
#include "gi/surface_cache/surface_cache_at_pixels.h"

#include <gtest/gtest.h>

namespace lumina::surface_cache {
namespace {

constexpr uint32_t kAtlas = 32;

// A floor card over x, z in [x0, x0 + 1] x [0, 1] at y = 0, facing +y, padded by `padding`, in the
// atlas rectangle (atlasX, 0, 16, 16): card u runs along x, v along z.
gpu::SurfaceCard floorCard(float x0, uint32_t atlasX, float padding) {
    gpu::SurfaceCard card{};
    card.worldToCard0 = glm::vec4(1.0f, 0.0f, 0.0f, -x0);
    card.worldToCard1 = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);
    card.worldToCard2 = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    card.boundsMinAndFlags = glm::vec4(x0 - padding, -padding, -padding, 0.0f);
    card.boundsMaxAndInstance = glm::vec4(x0 + 1.0f + padding, padding, 1.0f + padding, 0.0f);
    card.normalAndPadding = glm::vec4(0.0f, 1.0f, 0.0f, padding);
    card.atlasRect = glm::uvec4(atlasX, 0, 16, 16);
    return card;
}

TEST(SurfaceCacheAtPixels, APointInACardsPaddingReadsThatCardsEdgeNotItsAtlasNeighbour) {
    // Card 0 (atlas x 0..15) lies at world x in [0, 1]; card 1 (atlas x 16..31) at x in [2, 3].
    // A point at x = 1.95 lies in card 1's padding only, left of its rectangle: its texel column
    // is 15.2, inside card 0's rectangle, which must not be read.
    const std::vector<gpu::SurfaceCard> cards = {floorCard(0.0f, 0, 0.1f), floorCard(2.0f, 16, 0.1f)};
    std::vector<glm::vec4> finalLighting(kAtlas * kAtlas, glm::vec4(0.0f));
    for (uint32_t y = 0; y < 16; ++y) {
        for (uint32_t x = 0; x < kAtlas; ++x) {
            finalLighting[y * kAtlas + x] =
                x < 16 ? glm::vec4(100.0f, 100.0f, 100.0f, 1.0f) : glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
        }
    }
    image::Image position(2, 1, {"R", "G", "B", "A"});
    image::Image normal(2, 1, {"R", "G", "B", "A"});
    position.setRgb(0, 0, {1.95f, 0.0f, 0.5f}); // card 1's padding
    position.setRgb(1, 0, {0.5f, 0.0f, 0.5f});  // card 0's middle
    for (uint32_t x = 0; x < 2; ++x) {
        normal.setRgb(x, 0, {0.0f, 1.0f, 0.0f});
        normal.set("A", x, 0, 1.0f);
    }
    const CacheAtPixels out = cacheAtPixels(position, normal, finalLighting, kAtlas, cards);
    EXPECT_EQ(out.withoutCard, 0u);
    EXPECT_FLOAT_EQ(out.radiance.at("R", 0, 0), 0.5f);
    EXPECT_FLOAT_EQ(out.radiance.at("R", 1, 0), 100.0f);
}

} // namespace
} // namespace lumina::surface_cache
