// libFuzzer target for texture images (PNG, and JPEG, the other format glTF allows): every
// input goes through decodeTexture, which the glTF loader calls for each image a material
// uses. A TextureDecodeError is the expected answer to bad input; anything else is a bug.
#include "gi/scene/texture_decode.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace lumina::scene;
    // 64 MiB of texels, well inside libFuzzer's 2 GiB RSS limit.
    constexpr uint64_t kBudget = uint64_t(64) << 20;
    try {
        const Texture texture = decodeTexture(std::span<const uint8_t>(data, size), kBudget);
        if (texture.rgba8.size() != size_t(texture.width) * texture.height * 4 || texture.width == 0 ||
            texture.height == 0 || texture.width > kMaxTextureSide || texture.height > kMaxTextureSide) {
            std::abort(); // a decoded texture must be what it says it is
        }
    } catch (const TextureDecodeError&) {
    }
    return 0;
}
