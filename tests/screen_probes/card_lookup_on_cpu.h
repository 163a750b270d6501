#pragma once
// The GPU's card lookup (shaders/surface_cache/card_radiance.hlsli) on read-back atlas layers, for
// tests that check what a kernel read from the surface cache.
#include "shaders/screen_probes/screen_probe_shared.h"
#include "shaders/surface_cache/surface_card_shared.h"

#include <glm/glm.hpp>
#include <vector>

namespace lumina::test {

// Coverage-weighted bilinear around p's texel on `card`, clamped into the card's rectangle: the
// weights from `coverage`'s alpha (the final layer), the values from `value`'s rgb (the final
// layer again for cardRadiance; another layer of the atlas reads over the same footprint). a: the
// summed weight, 0 where nothing was captured.
inline glm::vec4 cardLayerOnCpu(const gpu::SurfaceCard& card, const std::vector<glm::vec4>& coverage,
                                const std::vector<glm::vec4>& value, uint32_t atlasSize, glm::vec3 p) {
    const glm::vec2 rectMin(float(card.atlasRect.x), float(card.atlasRect.y));
    const glm::vec2 rectMax = rectMin + glm::vec2(float(card.atlasRect.z), float(card.atlasRect.w)) - 1.0f;
    const glm::vec2 texel = gpu::cardToAtlasTexel(card, glm::vec2(gpu::worldToCardSpace(card, p)));
    const glm::vec2 x = glm::clamp(texel - 0.5f, rectMin, rectMax);
    const glm::vec2 base = glm::floor(x), f = x - base;
    glm::vec4 sum(0.0f);
    for (uint32_t corner = 0; corner < 4; ++corner) {
        const glm::vec2 offset(float(corner & 1u), float(corner >> 1));
        const glm::vec2 w2 = glm::mix(1.0f - f, f, offset);
        const glm::uvec2 at(glm::min(base + offset, rectMax));
        const size_t i = size_t(at.y) * atlasSize + at.x;
        const float w = w2.x * w2.y * coverage[i].a;
        sum += glm::vec4(w * glm::vec3(value[i]), w);
    }
    return sum.a > LUMINA_SP_MIN_COVERAGE ? glm::vec4(glm::vec3(sum) / sum.a, sum.a) : glm::vec4(0.0f);
}

} // namespace lumina::test
