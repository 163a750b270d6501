#pragma once
// Decoding a texture image (PNG or JPEG, glTF's formats) from its encoded bytes to RGBA8.
// The glTF loader calls it for each image a material uses; the PNG fuzzer
// (tests/fuzz/png_reader_fuzzer.cpp) calls it on its own.
#include "gi/scene/scene.h"

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

namespace lumina::scene {

// Why an image could not be decoded, e.g. "cannot decode (bad zlib header)" or "8192x8193
// texels is larger than 8192 per side"; the caller prefixes which image it was.
class TextureDecodeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Largest side accepted (stb_image's STBI_MAX_DIMENSIONS): 8192^2 RGBA8 texels are 256 MiB.
inline constexpr uint32_t kMaxTextureSide = 8192;

// `bytes` as a Texture (name left empty) of width * height * 4 bytes; TextureDecodeError when
// they are not a PNG or JPEG, are damaged, or decode to more than `maxTexelBytes`.
Texture decodeTexture(std::span<const uint8_t> bytes, uint64_t maxTexelBytes);

} // namespace lumina::scene
