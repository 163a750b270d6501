// Texture images: decoded (texture_decode.h) only for textures a material uses, with a
// budget over all of them and errors that name the image.
#include "gi/scene/gltf_internal.h"
#include "gi/scene/texture_decode.h"

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
    // Each image gets what the images before it left of the budget.
    uint64_t usedBytes = 0;
    for (const Texture& texture : scene.textures) {
        usedBytes += texture.rgba8.size();
    }
    const uint64_t budget = context.options.maxTextureBytes;
    Texture out;
    try {
        out = decodeTexture(bytes, usedBytes < budget ? budget - usedBytes : 0);
    } catch (const TextureDecodeError& error) {
        context.fail(imageWhat + ": " + error.what());
    }
    out.name = !image.name.empty() ? image.name
               : !image.uri.empty() && image.uri.rfind("data:", 0) != 0
                   ? image.uri
                   : "image " + std::to_string(imageIndex);
    imageTexture[imageIndex] = int64_t(scene.textures.size());
    scene.textures.push_back(std::move(out));
    return uint32_t(scene.textures.size() - 1);
}

} // namespace lumina::scene::gltf
