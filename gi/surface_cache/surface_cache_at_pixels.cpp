#include "gi/surface_cache/surface_cache_at_pixels.h"

#include "gi/surface_cache/card_bvh.h"

#include <algorithm>

namespace lumina::surface_cache {

CacheAtPixels cacheAtPixels(const image::Image& position, const image::Image& normal,
                            const std::vector<glm::vec4>& finalLighting, uint32_t atlasSize,
                            const std::vector<gpu::SurfaceCard>& cards) {
    CacheAtPixels out;
    out.radiance = image::Image(position.width(), position.height(), {"R", "G", "B", "A"});
    const CardBvh bvh = buildCardBvh(cards);
    for (uint32_t y = 0; y < position.height(); ++y) {
        for (uint32_t x = 0; x < position.width(); ++x) {
            if (normal.at("A", x, y) <= 0.0f) {
                continue; // no surface
            }
            const image::Rgb pos = position.rgbAt(x, y);
            const image::Rgb nrm = normal.rgbAt(x, y);
            const glm::vec3 p(pos.r, pos.g, pos.b);
            const glm::vec3 n = glm::normalize(glm::vec3(nrm.r, nrm.g, nrm.b));
            const CardOwner owner = findCardOwner(bvh, cards, p, n);
            if (owner.card == LUMINA_NO_CARD) {
                ++out.withoutCard;
                continue;
            }
            const gpu::SurfaceCard& card = cards[owner.card];
            const glm::vec2 texel = gpu::cardToAtlasTexel(card, glm::vec2(gpu::worldToCardSpace(card, p)));
            // Clamped into the card's own rectangle on both sides, as cardRadiance does: a point in
            // the card's padding reads the card's edge, never the atlas neighbour's texels.
            const uint32_t tx = std::clamp(uint32_t(std::max(texel.x, 0.0f)), card.atlasRect.x,
                                           card.atlasRect.x + card.atlasRect.z - 1);
            const uint32_t ty = std::clamp(uint32_t(std::max(texel.y, 0.0f)), card.atlasRect.y,
                                           card.atlasRect.y + card.atlasRect.w - 1);
            const glm::vec4 lighting = finalLighting[size_t(ty) * atlasSize + tx];
            out.radiance.setRgb(x, y, {lighting.r, lighting.g, lighting.b});
            out.radiance.set("A", x, y, 1.0f);
        }
    }
    return out;
}

} // namespace lumina::surface_cache
