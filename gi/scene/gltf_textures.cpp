// Texture images: decoded here rather than by tinygltf, only for textures a material uses,
// always to RGBA8, with a size limit and errors that name the image.
#include "gi/scene/gltf_internal.h"

#include <memory>

// stb_image compiled privately into this file (STB_IMAGE_STATIC), so it cannot clash with
// another library of the project that carries its own copy. PNG and JPEG are glTF's formats.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
// 8192^2 texels of RGBA8 is 256 MiB: larger textures are refused rather than allocated.
#define STBI_MAX_DIMENSIONS 8192
#include <stb/stb_image.h>

namespace lumina::scene::gltf {

namespace {

// The encoded bytes of image `index`: from its bufferView, or as tinygltf read them.
std::span<const uint8_t> encodedBytes(const Context& context, size_t index, const std::string& what) {
    const tinygltf::Model& model = context.model;
    const tinygltf::Image& image = model.images[index];
    if (image.bufferView < 0) {
        if (image.image.empty()) {
            context.fail(what + ": could not read '" + image.uri + "' (missing or empty file?)");
        }
        return image.image;
    }
    // precheckGltfJson checked the view against the declared buffer size; check again
    // against the bytes actually loaded.
    const tinygltf::BufferView& view = model.bufferViews.at(size_t(image.bufferView));
    const std::vector<unsigned char>& buffer = model.buffers.at(size_t(view.buffer)).data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
        context.fail(what + ": its bufferView runs past the end of its buffer");
    }
    return {buffer.data() + view.byteOffset, view.byteLength};
}

} // namespace

uint32_t convertTexture(const Context& context, int textureIndex, const std::string& what, Scene& scene,
                        std::vector<int64_t>& imageTexture) {
    const tinygltf::Model& model = context.model;
    if (textureIndex < 0 || size_t(textureIndex) >= model.textures.size()) {
        context.fail(what + ": texture " + std::to_string(textureIndex) + " does not exist");
    }
    const tinygltf::Texture& texture = model.textures[size_t(textureIndex)];
    if (texture.source < 0 || size_t(texture.source) >= model.images.size()) {
        context.fail(what + ": texture " + std::to_string(textureIndex) +
                     " has no image in a format Lumina reads (PNG or JPEG)");
    }
    const auto imageIndex = size_t(texture.source);
    if (imageTexture[imageIndex] >= 0) {
        return uint32_t(imageTexture[imageIndex]);
    }
    const tinygltf::Image& image = model.images[imageIndex];
    const std::string imageWhat =
        what + ": image " + std::to_string(imageIndex) +
        (image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? "" : " '" + image.uri + "'");
    const std::span<const uint8_t> bytes = encodedBytes(context, imageIndex, imageWhat);
    if (bytes.size() > size_t(INT32_MAX)) {
        context.fail(imageWhat + ": larger than 2 GiB");
    }
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4),
        stbi_image_free);
    if (!pixels) {
        context.fail(imageWhat + ": cannot decode (" + stbi_failure_reason() + ")");
    }
    uint64_t textureBytes = uint64_t(width) * uint64_t(height) * 4;
    for (const Texture& texture : scene.textures) {
        textureBytes += texture.rgba8.size();
    }
    if (textureBytes > context.options.maxTextureBytes) {
        context.fail(imageWhat + ": decoded textures would exceed " +
                     std::to_string(context.options.maxTextureBytes >> 20) + " MiB");
    }
    Texture out;
    out.name = !image.name.empty() ? image.name
               : !image.uri.empty() && image.uri.rfind("data:", 0) != 0
                   ? image.uri
                   : "image " + std::to_string(imageIndex);
    out.width = uint32_t(width);
    out.height = uint32_t(height);
    out.rgba8.assign(pixels.get(), pixels.get() + size_t(width) * size_t(height) * 4);
    imageTexture[imageIndex] = int64_t(scene.textures.size());
    scene.textures.push_back(std::move(out));
    return uint32_t(scene.textures.size() - 1);
}

} // namespace lumina::scene::gltf
