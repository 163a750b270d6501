#pragma once
// On-disk cache of mesh SDFs, so that a second run skips the build.
//
// Key: FNV-1a 64 (offset basis 14695981039346656037, prime 1099511628211) over, in order,
// kSdfCacheFormatVersion, the settings that change the result (resolution, padding,
// signRays, insideFraction's bits), the position count and bytes, and the index count and
// bytes. `threads` is left out: it never changes the result. Bump the version whenever the
// build's output or the file layout changes.
//
// File `<directory>/<key as 16 hex digits>.lsdf`, little-endian:
//   header (96 bytes): magic "LSDF", version u32, key u64, dims 3 x u32, voxelSize f32,
//                      volumeMin 3 x f32, triangle count u32, mesh bounds 6 x f32,
//                      payload bytes u64, payload FNV-1a 64, build seconds f64
//   payload: dims.x * dims.y * dims.z f32 distances, x fastest.
// A file whose size, magic, version, key, dims or payload hash does not check out is
// reported, rebuilt and overwritten; writes go to a temporary file renamed into place, so a
// crash mid-write never leaves a half file under the real name.
#include "gi/sdf/mesh_sdf.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace lumina::sdf {

inline constexpr uint32_t kSdfCacheFormatVersion = 1;

struct SdfCacheReport {
    bool fromCache = false;
    double seconds = 0.0; // this call: load or build-and-store
    std::filesystem::path file;
    std::string note; // why the cache was not used ("no file", "payload hash mismatch", ...) or ""
    // One line for logs: "sdf 64x40x32, 1234 triangles: built in 0.52 s (cache: no file)".
    std::string summary(const MeshSdf& sdf) const;
};

class SdfCache {
public:
    // $LUMINA_CACHE_DIR/sdf, else $XDG_CACHE_HOME/lumina/sdf, else ~/.cache/lumina/sdf
    // (%LOCALAPPDATA%\lumina\sdf on Windows), else <temp>/lumina/sdf.
    static std::filesystem::path defaultDirectory();
    static uint64_t key(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                        const SdfSettings& settings);

    explicit SdfCache(std::filesystem::path directory = defaultDirectory());

    // The cached SDF for this geometry and settings, else a fresh build, stored for next time
    // (a failure to store is noted in the report, not thrown).
    MeshSdf getOrBuild(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                       const SdfSettings& settings = {}, SdfCacheReport* report = nullptr);

    // nullopt with the reason in `why` when the file is missing or does not validate.
    std::optional<MeshSdf> load(uint64_t key, std::string* why = nullptr) const;
    // Returns false with the reason in `why` on an I/O failure.
    bool store(uint64_t key, const MeshSdf& sdf, std::string* why = nullptr) const;

    std::filesystem::path pathFor(uint64_t key) const;
    const std::filesystem::path& directory() const { return directory_; }

private:
    std::filesystem::path directory_;
};

// FNV-1a 64 continued over `bytes` from `hash`.
uint64_t fnv1a64(const void* bytes, size_t size, uint64_t hash = 14695981039346656037ull);

} // namespace lumina::sdf
