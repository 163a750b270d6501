// Texture images decoded by Lumina rather than by tinygltf: always to RGBA8, with a size
// limit checked from the header before any texel is allocated.
#include "gi/scene/texture_decode.h"

#include <memory>

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

Texture decodeTexture(std::span<const uint8_t> bytes, uint64_t maxTexelBytes) {
    if (bytes.size() > size_t(INT32_MAX)) {
        throw TextureDecodeError("larger than 2 GiB");
    }
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
