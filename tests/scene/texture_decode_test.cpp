// decodeTexture (gi/scene/texture_decode.h): a small PNG decodes to what it holds, and the
// inputs the PNG fuzzer once failed on (tests/fuzz/regressions/png_reader/) are refused with
// a TextureDecodeError before stb_image allocates what they declare.
#include "gi/scene/texture_decode.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <vector>

namespace lumina::scene {
namespace {

const std::filesystem::path kSource = LUMINA_TEST_SOURCE_DIR;
constexpr uint64_t kBudget = uint64_t(64) << 20;

std::vector<uint8_t> readBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

TEST(TextureDecode, ASmallPngDecodesToItsTexels) {
    const std::vector<uint8_t> bytes = readBytes(kSource / "tests/fuzz/seeds/png_reader/gray8_1x1.png");
    ASSERT_FALSE(bytes.empty());
    const Texture texture = decodeTexture(bytes, kBudget);
    EXPECT_EQ(texture.width, 1u);
    EXPECT_EQ(texture.height, 1u);
    EXPECT_EQ(texture.rgba8, (std::vector<uint8_t>{0x80, 0x80, 0x80, 0xff}));
}

TEST(TextureDecode, FuzzerFoundInputsAreRefusedWithTheReason) {
    const std::filesystem::path folder = kSource / "tests/fuzz/regressions/png_reader";
    ASSERT_TRUE(std::filesystem::is_directory(folder));
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        SCOPED_TRACE(entry.path().string());
        try {
            (void)decodeTexture(readBytes(entry.path()), kBudget);
            ADD_FAILURE() << "expected a TextureDecodeError";
        } catch (const TextureDecodeError& error) {
            EXPECT_NE(std::string(error.what()).find("declares"), std::string::npos) << error.what();
        }
    }
}

} // namespace
} // namespace lumina::scene
