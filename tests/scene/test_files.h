#pragma once
// Helpers for the scene tests: a fresh temporary folder per test, small glTF documents built
// in code (so each bad-input case is one edit away from a valid file), and where things are.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lumina::scene::test {

// A folder under the system's temp folder, removed when the object goes.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path write(const std::string& name, const std::string& text) const;
    std::filesystem::path write(const std::string& name, const std::vector<uint8_t>& bytes) const;

private:
    std::filesystem::path path_;
};

// The repository's source folder: $LUMINA_SOURCE_DIR, else the one this test was built from.
std::filesystem::path sourceDir();

// Debian's assimp-testmodels.
std::filesystem::path assimpModels();

std::string base64(const std::vector<uint8_t>& bytes);

// A valid glTF holding one mesh of `triangles` (positions as given, 3 per triangle, no
// indices unless `indices` is non-empty), one node, one material; buffer embedded.
nlohmann::json triangleGltf(const std::vector<float>& positions, const std::vector<uint32_t>& indices = {});

// The same document's buffer as raw bytes (for .glb and external .bin cases).
std::vector<uint8_t> gltfBuffer(const std::vector<float>& positions,
                                const std::vector<uint32_t>& indices = {});

// A .glb container around `json` and `bin`.
std::vector<uint8_t> makeGlb(const nlohmann::json& json, const std::vector<uint8_t>& bin);

// One unit quad at z = 0 (two triangles, front face +z), as positions for triangleGltf.
std::vector<float> unitQuad();

} // namespace lumina::scene::test
