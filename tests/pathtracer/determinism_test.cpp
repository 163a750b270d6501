// Accumulation is deterministic for a seed: the random numbers of a path depend only on
// (seed, pixel, sample index), so splitting the samples over submissions or the image over
// tiles changes nothing, bit for bit; another seed gives another image.
#include "tests/pathtracer/path_tracer_fixture.h"

#include <cstring>

namespace lumina::test {
namespace {

using DeterminismTest = PathTracerTest;

constexpr uint32_t kSize = 32;
constexpr uint32_t kSpp = 8;

bool sameBits(const image::Image& a, const image::Image& b) {
    if (!a.sameSize(b) || a.channelNames() != b.channelNames()) {
        return false;
    }
    for (const std::string& name : a.channelNames()) {
        const auto x = a.channel(name);
        const auto y = b.channel(name);
        if (std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) != 0) {
            return false;
        }
    }
    return true;
}

TEST_P(DeterminismTest, SameSeedSameImageWhateverTheSplit) {
    const scene::Scene scene = loadBuiltin("cornell_box", kSize, kSize);
    gi::PathTracerSettings settings;
    settings.aovs = true;
    settings.seed = 3;
    const gi::PathTracerResult whole = render(scene, settings, kSpp, kSpp);

    gi::PathTracerSettings tiled = settings;
    tiled.maxPixelsPerDispatch = kSize * 8; // four bands of eight rows
    const gi::PathTracerResult split = render(scene, tiled, kSpp, 3);
    EXPECT_EQ(split.samples, kSpp);
    EXPECT_EQ(split.rays, whole.rays);
    EXPECT_TRUE(sameBits(whole.image, split.image)) << "tiles and submissions changed the result";

    gi::PathTracerSettings reseeded = settings;
    reseeded.seed = 4;
    const gi::PathTracerResult other = render(scene, reseeded, kSpp, kSpp);
    EXPECT_FALSE(sameBits(whole.image, other.image)) << "the seed changed nothing";
    EXPECT_EQ(whole.nonFiniteSamples, 0u);
}

// A band of rows (a shard of `lumina reference --shard`) is exactly those rows of the whole
// image, so the bands of an image stitch into it bit for bit; a band that ends off the
// 8-row group grid (rows 5..17) is the case where the last group runs past the band.
TEST_P(DeterminismTest, ABandOfRowsIsThoseRowsOfTheWholeImage) {
    const scene::Scene scene = loadBuiltin("cornell_box", kSize, kSize);
    gi::PathTracerSettings settings;
    settings.aovs = true;
    const gi::PathTracerResult whole = render(scene, settings, kSpp, kSpp);

    gi::PathTracerSettings band = settings;
    band.firstRow = 5;
    band.rowCount = 13;
    const gi::PathTracerResult part = render(scene, band, kSpp, kSpp);
    ASSERT_EQ(part.image.width(), kSize);
    ASSERT_EQ(part.image.height(), band.rowCount);
    ASSERT_EQ(part.image.channelNames(), whole.image.channelNames());
    for (const std::string& name : whole.image.channelNames()) {
        const auto rows =
            whole.image.channel(name).subspan(size_t(band.firstRow) * kSize, part.image.pixelCount());
        EXPECT_EQ(std::memcmp(rows.data(), part.image.channel(name).data(), rows.size_bytes()), 0)
            << "channel " << name << " of rows 5..17 differs from the whole image's";
    }
    EXPECT_LT(part.rays, whole.rays);
}

LUMINA_INSTANTIATE_GPU_TEST(DeterminismTest);

} // namespace
} // namespace lumina::test
