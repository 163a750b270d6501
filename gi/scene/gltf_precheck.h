#pragma once
// Checks made on a glTF's raw bytes before tinygltf sees them. tinygltf 2.7 trusts a few
// things it should not (an image's bufferView bounds, how deeply JSON nests); these checks
// turn such input into a SceneError instead of an out-of-bounds read or a stack overflow.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

namespace lumina::scene {

// Deeper JSON than this is refused: no glTF needs it, and tinygltf copies extensions and
// extras recursively.
inline constexpr int kMaxJsonDepth = 64;

struct GltfContainer {
    std::string_view json;     // the JSON text (the whole file for .gltf, chunk 0 for .glb)
    uint64_t binChunkSize = 0; // bytes of the GLB BIN chunk, 0 without one
};

// glTF extensions a file may list in extensionsRequired: those Lumina honours.
bool isSupportedRequiredExtension(std::string_view name);

// Splits a .glb into its chunks, checking the header's lengths against the data; for
// .gltf text returns it whole.
GltfContainer readGltfContainer(std::span<const uint8_t> bytes, bool binary,
                                const std::filesystem::path& file);

// Checks nesting depth, the version, required extensions, and that every image stored in a
// bufferView lies inside its buffer's declared byteLength.
void precheckGltfJson(std::string_view json, const std::filesystem::path& file);

} // namespace lumina::scene
