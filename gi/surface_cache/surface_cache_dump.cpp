#include "gi/surface_cache/surface_cache_dump.h"

#include "gi/image/exr.h"
#include "gi/image/png.h"
#include "rhi/transfer.h"
#include "shaders/common/constants_shared.h"
#include "shaders/surface_cache/surface_cache_lighting_shared.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lumina::surface_cache {

namespace {

image::Image texelImage(const std::vector<glm::vec4>& texels, uint32_t size, bool alpha) {
    image::Image out = alpha ? image::Image::rgba(size, size) : image::Image::rgb(size, size);
    const char* names[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < (alpha ? 4 : 3); ++c) {
        std::span<float> plane = out.channel(names[c]);
        for (size_t i = 0; i < texels.size(); ++i) {
            plane[i] = texels[i][c];
        }
    }
    return out;
}

std::string fileStem(AtlasLayer layer) {
    std::string name = atlasLayerName(layer);
    std::replace(name.begin(), name.end(), ' ', '_');
    return "surface_cache_" + name;
}

// A colour per card index that neighbours rarely share (golden-ratio hue steps).
image::Rgb cardColour(uint32_t card) {
    const float hue = std::fmod(float(card) * 0.618034f, 1.0f) * 6.0f;
    const float x = 1.0f - std::fabs(std::fmod(hue, 2.0f) - 1.0f);
    const int sector = int(hue);
    const float rgb[6][3] = {{1, x, 0}, {x, 1, 0}, {0, 1, x}, {0, x, 1}, {x, 0, 1}, {1, 0, x}};
    return {0.2f + 0.8f * rgb[sector][0], 0.2f + 0.8f * rgb[sector][1], 0.2f + 0.8f * rgb[sector][2]};
}

float shIrradiance(const gpu::float4& sh, const glm::vec3& n) {
    const float l1 = sh.y * n.x + sh.z * n.y + sh.w * n.z;
    return std::max(LUMINA_PI * LUMINA_SH_Y00 * sh.x + (2.0f * LUMINA_PI / 3.0f) * LUMINA_SH_Y1 * l1, 0.0f);
}

} // namespace

std::vector<std::filesystem::path> dumpSurfaceCache(rhi::IDevice& device, const SurfaceCache& cache,
                                                    const std::filesystem::path& directory,
                                                    const image::DisplayOptions& display) {
    std::filesystem::create_directories(directory);
    std::vector<std::filesystem::path> written;
    const auto exr = [&](const std::string& stem, const image::Image& image) {
        written.push_back(directory / (stem + ".exr"));
        image::writeExr(written.back(), image);
    };
    const auto png = [&](const std::string& stem, const image::Image& image,
                         const image::DisplayOptions& how) {
        written.push_back(directory / (stem + ".png"));
        image::writePng(written.back(), image, how);
    };
    const image::DisplayOptions clamp{.tonemap = image::Tonemap::Clamp};
    const uint32_t size = cache.atlas().size();

    image::Image finalLayer;
    for (uint32_t l = 0; l < kAtlasLayerCount; ++l) {
        const auto layer = AtlasLayer(l);
        image::Image texels = texelImage(cache.readLayer(layer), size, true);
        exr(fileStem(layer), texels);
        texels.removeChannel("A");
        if (layer == AtlasLayer::Normal) {
            for (const char* c : {"R", "G", "B"}) {
                for (float& v : texels.channel(c)) {
                    v = 0.5f * v + 0.5f;
                }
            }
        }
        const bool radiance = layer == AtlasLayer::DirectLight || layer == AtlasLayer::IndirectLight ||
                              layer == AtlasLayer::FinalLighting;
        png(fileStem(layer), texels, radiance ? display : clamp);
        if (layer == AtlasLayer::FinalLighting) {
            finalLayer = std::move(texels);
        }
    }

    // Card outlines over the final layer, and each texel's card.
    const std::vector<gpu::SurfaceCard>& cards = cache.cards().cards();
    image::Image outlined = image::toDisplay(finalLayer, display);
    for (const gpu::SurfaceCard& card : cards) {
        if (card.atlasRect.z == 0) {
            continue; // evicted: no texels
        }
        const uint32_t x0 = card.atlasRect.x, y0 = card.atlasRect.y;
        const uint32_t x1 = x0 + card.atlasRect.z - 1, y1 = y0 + card.atlasRect.w - 1;
        for (uint32_t x = x0; x <= x1; ++x) {
            outlined.setRgb(x, y0, {1.0f, 1.0f, 1.0f});
            outlined.setRgb(x, y1, {1.0f, 1.0f, 1.0f});
        }
        for (uint32_t y = y0; y <= y1; ++y) {
            outlined.setRgb(x0, y, {1.0f, 1.0f, 1.0f});
            outlined.setRgb(x1, y, {1.0f, 1.0f, 1.0f});
        }
    }
    written.push_back(directory / "surface_cache_cards.png");
    image::writeDisplayPng(written.back(), outlined);

    const std::vector<uint32_t>& owners = cache.cards().atlas().ownerTable();
    const uint32_t tilesX = cache.cards().atlas().tilesX();
    image::Image ids(size, size, {"card"});
    image::Image idColours = image::Image::rgb(size, size);
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            const uint32_t owner = owners[(y / kTileSize) * tilesX + x / kTileSize];
            ids.set("card", x, y, owner == kNoOwner ? -1.0f : float(owner));
            if (owner != kNoOwner) {
                idColours.setRgb(x, y, cardColour(owner));
            }
        }
    }
    exr("surface_cache_card_ids", ids);
    png("surface_cache_card_ids", idColours, clamp);

    // Radiosity probes: the irradiance each probe's SH gives at its own normal.
    const auto probes = rhi::readBufferAs<gpu::RadiosityProbe>(device, *cache.radiosity().probes());
    const uint32_t side = size / LUMINA_RADIOSITY_PROBE_SPACING;
    image::Image probeImage = image::Image::rgba(side, side);
    for (uint32_t y = 0; y < side; ++y) {
        for (uint32_t x = 0; x < side; ++x) {
            const size_t i = size_t(y) * side + x;
            if (i >= probes.size()) {
                continue;
            }
            const gpu::RadiosityProbe& p = probes[i];
            const bool valid = p.normalAndTexel.w != 0.0f;
            const glm::vec3 n(p.normalAndTexel.x, p.normalAndTexel.y, p.normalAndTexel.z);
            probeImage.setRgb(
                x, y,
                valid ? image::Rgb{shIrradiance(p.r, n), shIrradiance(p.g, n), shIrradiance(p.b, n)}
                      : image::Rgb{});
            probeImage.set("A", x, y, valid ? 1.0f : 0.0f);
        }
    }
    exr("surface_cache_radiosity_probes", probeImage);
    image::Image probeRgb = probeImage;
    probeRgb.removeChannel("A");
    png("surface_cache_radiosity_probes", probeRgb, display);

    // Voxel lighting: z slices left to right, one row of slices per face (+x, -x, +y, -y, +z, -z).
    const gpu::VoxelGridInfo& grid = cache.voxelLighting().grid();
    const std::vector<glm::vec4> voxels = cache.readVoxelLighting();
    const uint32_t nx = grid.dims.x, ny = grid.dims.y, nz = grid.dims.z, faces = LUMINA_VOXEL_FACES;
    image::Image slices = image::Image::rgba(nx * nz, ny * faces);
    for (uint32_t f = 0; f < faces; ++f) {
        for (uint32_t z = 0; z < nz; ++z) {
            for (uint32_t y = 0; y < ny; ++y) {
                for (uint32_t x = 0; x < nx; ++x) {
                    const glm::vec4 v = voxels[(size_t(z) * ny + y) * nx * faces + f * nx + x];
                    // y up in the world, down the image rows
                    const uint32_t row = f * ny + ny - 1 - y;
                    slices.setRgb(z * nx + x, row, {v.r, v.g, v.b});
                    slices.set("A", z * nx + x, row, v.a);
                }
            }
        }
    }
    exr("surface_cache_voxel_lighting", slices);
    return written;
}

} // namespace lumina::surface_cache
