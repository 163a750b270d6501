// Texture images decoded by Lumina rather than by tinygltf: always to RGBA8, with a size
// limit checked from the header before any texel is allocated.
#include "gi/scene/texture_decode.h"

#include <algorithm>
#include <cctype>
#include <memory>
#include <string>

// stb_image compiled privately into this file (STB_IMAGE_STATIC), so it cannot clash with
// another library of the project that carries its own copy. PNG and JPEG are glTF's formats.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_MAX_DIMENSIONS 8192 // kMaxTextureSide
#include <stb/stb_image.h>

namespace lumina::scene {

static_assert(kMaxTextureSide == STBI_MAX_DIMENSIONS);

namespace {

// stb_image trusts a PNG chunk's declared length and allocates for it before reading it: a
// 40 KiB file whose IDAT declares 2 GiB made it allocate 2 GiB (found by the PNG fuzzer,
// tests/fuzz/regressions/png_reader/). Every chunk must fit in the bytes the file has.
void checkPngChunks(std::span<const uint8_t> bytes) {
    constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin())) {
        return; // not a PNG: stb_image decides what it is
    }
    size_t offset = 8;
    while (bytes.size() - offset >= 8) {
        const uint8_t* chunk = bytes.data() + offset;
        const uint64_t length =
            uint64_t(chunk[0]) << 24 | uint64_t(chunk[1]) << 16 | uint64_t(chunk[2]) << 8 | chunk[3];
        const bool named = std::all_of(chunk + 4, chunk + 8, [](uint8_t c) { return std::isalpha(c) != 0; });
        const std::string type = named ? std::string(chunk + 4, chunk + 8) : "?";
        if (length + 12 > bytes.size() - offset) { // length, type, data, CRC
            throw TextureDecodeError("PNG chunk '" + type + "' at byte " + std::to_string(offset) +
                                     " declares " + std::to_string(length) + " bytes, more than the " +
                                     std::to_string(bytes.size() - offset) + " left in the file");
        }
        offset += size_t(length) + 12;
        if (type == "IEND") {
            return;
        }
    }
}

// stb_image (Debian's 2.27) builds a JPEG Huffman table from the sixteen code counts a DHT
// segment declares without checking that they total at most 256 symbols, and writes past its
// 257-entry size list when they do (found by the PNG/JPEG fuzzer,
// tests/fuzz/regressions/png_reader/jpeg_dht_*). Every table of every DHT segment must declare at
// most 256 symbols and fit in its segment. Progressive JPEGs put DHT segments between scans, so
// the walk continues past each scan's entropy-coded data.
void checkJpegHuffmanTables(std::span<const uint8_t> bytes) {
    // stb_image takes fill bytes (0xFF) before any marker, the start of image (SOI) included.
    size_t offset = 0;
    while (offset < bytes.size() && bytes[offset] == 0xFF) {
        ++offset;
    }
    if (offset == 0 || offset >= bytes.size() || bytes[offset] != 0xD8) {
        return; // not a JPEG
    }
    ++offset;
    const auto fail = [](size_t at, const std::string& what) {
        throw TextureDecodeError("JPEG Huffman table at byte " + std::to_string(at) + ": " + what);
    };
    while (offset < bytes.size()) {
        if (bytes[offset] != 0xFF) {
            ++offset; // entropy-coded data of a scan: markers are found by their 0xFF
            continue;
        }
        while (offset < bytes.size() && bytes[offset] == 0xFF) {
            ++offset; // fill bytes before a marker
        }
        if (offset >= bytes.size()) {
            return;
        }
        const uint8_t marker = bytes[offset++];
        // Stuffed zero, restart markers, TEM and SOI have no segment; EOI ends the image.
        if (marker == 0x00 || (marker >= 0xD0 && marker <= 0xD8) || marker == 0x01) {
            continue;
        }
        if (marker == 0xD9 || bytes.size() - offset < 2) {
            return;
        }
        const size_t length = size_t(bytes[offset]) << 8 | bytes[offset + 1];
        if (marker == 0xC4 && (length < 2 || length > bytes.size() - offset)) {
            // stb_image would read zeros past the end: the counts it read would still be these.
            fail(offset, "its segment declares " + std::to_string(length) + " bytes, more than the " +
                             std::to_string(bytes.size() - offset) + " left in the file");
        }
        if (length < 2 || length > bytes.size() - offset) {
            return; // a segment past the end holds no table that is not caught above
        }
        if (marker == 0xC4) {
            size_t table = offset + 2;
            const size_t end = offset + length;
            while (table < end) {
                if (end - table < 17) {
                    fail(table, "fewer than the 17 bytes of a table header left in its segment");
                }
                size_t symbols = 0;
                for (size_t i = 1; i <= 16; ++i) {
                    symbols += bytes[table + i];
                }
                if (symbols > 256) {
                    fail(table, "declares " + std::to_string(symbols) + " codes, at most 256");
                }
                if (symbols > end - table - 17) {
                    fail(table,
                         "declares " + std::to_string(symbols) + " codes, more than its segment holds");
                }
                table += 17 + symbols;
            }
        }
        offset += length;
    }
}

} // namespace

Texture decodeTexture(std::span<const uint8_t> bytes, uint64_t maxTexelBytes) {
    if (bytes.size() > size_t(INT32_MAX)) {
        throw TextureDecodeError("larger than 2 GiB");
    }
    checkPngChunks(bytes);
    checkJpegHuffmanTables(bytes);
    auto checkSize = [maxTexelBytes](int width, int height) {
        if (uint64_t(width) * uint64_t(height) * 4 > maxTexelBytes) {
            throw TextureDecodeError(std::to_string(width) + "x" + std::to_string(height) +
                                     " texels: decoded textures would exceed " +
                                     std::to_string(maxTexelBytes >> 20) + " MiB");
        }
    };
    // The header first: a small file may declare a huge image, refused before decoding.
    int width = 0, height = 0, channels = 0;
    if (stbi_info_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels)) {
        checkSize(width, height);
    }
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4),
        stbi_image_free);
    if (!pixels) {
        throw TextureDecodeError(std::string("cannot decode (") + stbi_failure_reason() + ")");
    }
    checkSize(width, height);
    Texture texture;
    texture.width = uint32_t(width);
    texture.height = uint32_t(height);
    texture.rgba8.assign(pixels.get(), pixels.get() + size_t(width) * size_t(height) * 4);
    return texture;
}

} // namespace lumina::scene
