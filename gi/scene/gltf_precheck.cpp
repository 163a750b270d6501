#include "gi/scene/gltf_precheck.h"

#include "gi/scene/scene_error.h"

#include <cstring>
#include <nlohmann/json.hpp>
#include <string>

namespace lumina::scene {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67; // "glTF"
constexpr uint32_t kGlbChunkJson = 0x4E4F534A;
constexpr uint32_t kGlbChunkBin = 0x004E4942;
constexpr size_t kGlbHeaderBytes = 12;
constexpr size_t kGlbChunkHeaderBytes = 8;

uint32_t readLe32(const uint8_t* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

bool isIndex(const nlohmann::json& value) {
    return value.is_number_unsigned();
}

// The unsigned integer `key` of `object`, `fallback` when absent; nullopt-like -1 when bad.
int64_t unsignedMember(const nlohmann::json& object, const char* key, int64_t fallback) {
    const auto it = object.find(key);
    if (it == object.end()) {
        return fallback;
    }
    if (!it->is_number_unsigned() || it->get<uint64_t>() > uint64_t(INT64_MAX)) {
        return -1;
    }
    return int64_t(it->get<uint64_t>());
}

} // namespace

bool isSupportedRequiredExtension(std::string_view name) {
    return name == "KHR_lights_punctual" || name == "KHR_materials_emissive_strength" ||
           name == "KHR_mesh_quantization";
}

GltfContainer readGltfContainer(std::span<const uint8_t> bytes, bool binary,
                                const std::filesystem::path& file) {
    if (!binary) {
        return {std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), 0};
    }
    if (bytes.size() < kGlbHeaderBytes + kGlbChunkHeaderBytes) {
        throw SceneError(file, "truncated GLB: " + std::to_string(bytes.size()) +
                                   " bytes, shorter than the 20-byte header");
    }
    if (readLe32(bytes.data()) != kGlbMagic) {
        throw SceneError(file, "not a GLB file (its first four bytes are not 'glTF')");
    }
    const uint32_t version = readLe32(bytes.data() + 4);
    if (version != 2) {
        throw SceneError(file, "GLB container version " + std::to_string(version) +
                                   " (only glTF 2.0 is supported)");
    }
    const uint64_t length = readLe32(bytes.data() + 8);
    if (length > bytes.size()) {
        throw SceneError(file, "truncated GLB: its header says " + std::to_string(length) +
                                   " bytes, the file has " + std::to_string(bytes.size()));
    }
    const uint64_t jsonLength = readLe32(bytes.data() + 12);
    if (readLe32(bytes.data() + 16) != kGlbChunkJson) {
        throw SceneError(file, "malformed GLB: the first chunk is not JSON");
    }
    const uint64_t jsonEnd = kGlbHeaderBytes + kGlbChunkHeaderBytes + jsonLength;
    if (jsonLength == 0 || jsonEnd > length) {
        throw SceneError(file, "truncated GLB: the JSON chunk (" + std::to_string(jsonLength) +
                                   " bytes) runs past the end of the data (" + std::to_string(length) +
                                   " bytes)");
    }
    GltfContainer container;
    container.json =
        std::string_view(reinterpret_cast<const char*>(bytes.data()) + kGlbHeaderBytes + kGlbChunkHeaderBytes,
                         size_t(jsonLength));
    if (jsonEnd + kGlbChunkHeaderBytes <= length) {
        const uint64_t binLength = readLe32(bytes.data() + jsonEnd);
        const uint32_t binType = readLe32(bytes.data() + jsonEnd + 4);
        if (binType == kGlbChunkBin) {
            if (jsonEnd + kGlbChunkHeaderBytes + binLength > length) {
                throw SceneError(file, "truncated GLB: the BIN chunk (" + std::to_string(binLength) +
                                           " bytes) runs past the end of the data (" +
                                           std::to_string(length) + " bytes)");
            }
            container.binChunkSize = binLength;
        }
    }
    return container;
}

void precheckGltfJson(std::string_view json, const std::filesystem::path& file) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(
            json.begin(), json.end(), [&](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
                if (depth > kMaxJsonDepth) {
                    throw SceneError(file,
                                     "JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
                }
                return true;
            });
    } catch (const nlohmann::json::exception& error) {
        throw SceneError(file, std::string("malformed JSON: ") + error.what());
    }
    if (!document.is_object()) {
        throw SceneError(file, "malformed glTF: the top level is not a JSON object");
    }
    // Version and required extensions first: a glTF 1.0 or Draco file fails here with the
    // real reason rather than with whatever tinygltf trips over in it.
    if (const auto asset = document.find("asset"); asset != document.end() && asset->is_object()) {
        const auto version = asset->find("version");
        if (version != asset->end() && version->is_string() &&
            version->get<std::string>().rfind("2.", 0) != 0) {
            throw SceneError(file, "glTF version '" + version->get<std::string>() +
                                       "' is not supported (glTF 2.0 only)");
        }
    }
    if (const auto required = document.find("extensionsRequired");
        required != document.end() && required->is_array()) {
        for (const nlohmann::json& name : *required) {
            if (name.is_string() && !isSupportedRequiredExtension(name.get<std::string>())) {
                throw SceneError(file, "requires extension " + name.get<std::string>() +
                                           ", which Lumina does not support");
            }
        }
    }
    const auto images = document.find("images");
    if (images == document.end() || !images->is_array()) {
        return;
    }
    const auto views = document.find("bufferViews");
    const auto buffers = document.find("buffers");
    for (size_t i = 0; i < images->size(); ++i) {
        const nlohmann::json& image = (*images)[i];
        if (!image.is_object() || !image.contains("bufferView")) {
            continue;
        }
        const std::string what = "image " + std::to_string(i) + ": ";
        const nlohmann::json& viewIndex = image["bufferView"];
        if (!isIndex(viewIndex) || views == document.end() || !views->is_array() ||
            viewIndex.get<uint64_t>() >= views->size() || !(*views)[viewIndex.get<size_t>()].is_object()) {
            throw SceneError(file, what + "bufferView " + viewIndex.dump() + " does not exist");
        }
        const nlohmann::json& view = (*views)[viewIndex.get<size_t>()];
        const nlohmann::json bufferIndex = view.value("buffer", nlohmann::json());
        if (!isIndex(bufferIndex) || buffers == document.end() || !buffers->is_array() ||
            bufferIndex.get<uint64_t>() >= buffers->size() ||
            !(*buffers)[bufferIndex.get<size_t>()].is_object()) {
            throw SceneError(file, what + "its bufferView names buffer " + bufferIndex.dump() +
                                       ", which does not exist");
        }
        const int64_t offset = unsignedMember(view, "byteOffset", 0);
        const int64_t size = unsignedMember(view, "byteLength", -1);
        const int64_t bufferSize = unsignedMember((*buffers)[bufferIndex.get<size_t>()], "byteLength", -1);
        if (offset < 0 || size < 0 || bufferSize < 0 || offset > bufferSize || size > bufferSize - offset) {
            throw SceneError(file, what + "bufferView " + viewIndex.dump() + " (offset " +
                                       std::to_string(offset) + ", length " + std::to_string(size) +
                                       ") does not fit buffer " + bufferIndex.dump() + " (" +
                                       std::to_string(bufferSize) + " bytes)");
        }
    }
}

} // namespace lumina::scene
