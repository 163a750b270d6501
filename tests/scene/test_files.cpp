#include "tests/scene/test_files.h"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>

namespace lumina::scene::test {

namespace fs = std::filesystem;

TempDir::TempDir() {
    static std::atomic<uint32_t> counter{0};
    std::random_device random;
    path_ = fs::temp_directory_path() /
            ("lumina_scene_test_" + std::to_string(random()) + "_" + std::to_string(counter++));
    fs::create_directories(path_);
}

TempDir::~TempDir() {
    std::error_code error;
    fs::remove_all(path_, error);
}

fs::path TempDir::write(const std::string& name, const std::string& text) const {
    const fs::path file = path_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

fs::path TempDir::write(const std::string& name, const std::vector<uint8_t>& bytes) const {
    const fs::path file = path_ / name;
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return file;
}

fs::path sourceDir() {
    const char* dir = std::getenv("LUMINA_SOURCE_DIR");
    return dir && *dir ? fs::path(dir) : fs::path(LUMINA_TEST_SOURCE_DIR);
}

fs::path assimpModels() {
    return "/usr/share/assimp/models";
}

std::string base64(const std::vector<uint8_t>& bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t(bytes[i]) << 16 |
                           (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) |
                           (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0);
        out += kAlphabet[(n >> 18) & 63];
        out += kAlphabet[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
    }
    return out;
}

std::vector<uint8_t> gltfBuffer(const std::vector<float>& positions, const std::vector<uint32_t>& indices) {
    std::vector<uint8_t> bytes(positions.size() * 4 + indices.size() * 4);
    std::memcpy(bytes.data(), positions.data(), positions.size() * 4);
    if (!indices.empty()) {
        std::memcpy(bytes.data() + positions.size() * 4, indices.data(), indices.size() * 4);
    }
    return bytes;
}

nlohmann::json triangleGltf(const std::vector<float>& positions, const std::vector<uint32_t>& indices) {
    const std::vector<uint8_t> bytes = gltfBuffer(positions, indices);
    nlohmann::json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}, {"name", "node"}}}},
        {"materials",
         {{{"name", "grey"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}}}}}}},
        {"meshes",
         {{{"name", "mesh"}, {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 0}}}}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", positions.size() / 3}, {"type", "VEC3"}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positions.size() * 4}}}},
        {"buffers",
         {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}},
    };
    if (!indices.empty()) {
        doc["accessors"].push_back(
            {{"bufferView", 1}, {"componentType", 5125}, {"count", indices.size()}, {"type", "SCALAR"}});
        doc["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", positions.size() * 4}, {"byteLength", indices.size() * 4}});
        doc["meshes"][0]["primitives"][0]["indices"] = 1;
    }
    return doc;
}

std::vector<uint8_t> makeGlb(const nlohmann::json& json, const std::vector<uint8_t>& bin) {
    std::string text = json.dump();
    while (text.size() % 4 != 0) {
        text += ' ';
    }
    std::vector<uint8_t> padded = bin;
    while (padded.size() % 4 != 0) {
        padded.push_back(0);
    }
    std::vector<uint8_t> out;
    auto put32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i) {
            out.push_back(uint8_t(v >> (8 * i)));
        }
    };
    const uint32_t total =
        12 + 8 + uint32_t(text.size()) + (padded.empty() ? 0 : 8 + uint32_t(padded.size()));
    put32(0x46546C67);
    put32(2);
    put32(total);
    put32(uint32_t(text.size()));
    put32(0x4E4F534A);
    out.insert(out.end(), text.begin(), text.end());
    if (!padded.empty()) {
        put32(uint32_t(padded.size()));
        put32(0x004E4942);
        out.insert(out.end(), padded.begin(), padded.end());
    }
    return out;
}

std::vector<float> unitQuad() {
    return {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
}

} // namespace lumina::scene::test
