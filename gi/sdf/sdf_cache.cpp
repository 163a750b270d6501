#include "gi/sdf/sdf_cache.h"

#include "gi/core/cache_dir.h"

#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

namespace lumina::sdf {
namespace {

static_assert(std::endian::native == std::endian::little, "the SDF cache format is little-endian");

constexpr char kMagic[4] = {'L', 'S', 'D', 'F'};
constexpr size_t kHeaderSize = 96;
constexpr uint32_t kMaxCachedDim = 4096;

// Field-by-field header serialisation: no struct padding reaches the file.
class Writer {
public:
    template <typename T>
    void put(const T& value) {
        const auto* p = reinterpret_cast<const char*>(&value);
        bytes.insert(bytes.end(), p, p + sizeof(T));
    }
    std::vector<char> bytes;
};

class Reader {
public:
    explicit Reader(const char* data) : data_(data) {}
    template <typename T>
    T get() {
        T value;
        std::memcpy(&value, data_ + offset_, sizeof(T));
        offset_ += sizeof(T);
        return value;
    }

private:
    const char* data_;
    size_t offset_ = 0;
};

} // namespace

uint64_t fnv1a64(const void* bytes, size_t size, uint64_t hash) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    for (size_t i = 0; i < size; ++i) {
        hash ^= p[i];
        hash *= 1099511628211ull;
    }
    return hash;
}

std::string SdfCacheReport::summary(const MeshSdf& sdf) const {
    std::ostringstream out;
    out << "sdf " << sdf.dims.x << "x" << sdf.dims.y << "x" << sdf.dims.z << ", " << sdf.stats.triangles
        << " triangles: ";
    out.setf(std::ios::fixed);
    out.precision(3);
    if (fromCache) {
        out << "loaded from cache in " << seconds << " s";
    } else {
        out << "built in " << sdf.stats.seconds << " s";
        if (!note.empty()) {
            out << " (cache: " << note << ")";
        }
    }
    return out.str();
}

std::filesystem::path SdfCache::defaultDirectory() {
    return gi::cacheRoot() / "sdf";
}

uint64_t SdfCache::key(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                       const SdfSettings& settings) {
    uint64_t hash = fnv1a64(&kSdfCacheFormatVersion, sizeof(kSdfCacheFormatVersion));
    const uint32_t fields[] = {settings.resolution, settings.padding, settings.signRays,
                               std::bit_cast<uint32_t>(settings.insideFraction)};
    hash = fnv1a64(fields, sizeof(fields), hash);
    const uint64_t counts[] = {positions.size(), indices.size()};
    hash = fnv1a64(&counts[0], sizeof(uint64_t), hash);
    hash = fnv1a64(positions.data(), positions.size_bytes(), hash);
    hash = fnv1a64(&counts[1], sizeof(uint64_t), hash);
    return fnv1a64(indices.data(), indices.size_bytes(), hash);
}

SdfCache::SdfCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

std::filesystem::path SdfCache::pathFor(uint64_t key) const {
    char name[32];
    std::snprintf(name, sizeof(name), "%016llx.lsdf", static_cast<unsigned long long>(key));
    return directory_ / name;
}

std::optional<MeshSdf> SdfCache::load(uint64_t key, std::string* why) const {
    auto fail = [&](const std::string& reason) -> std::optional<MeshSdf> {
        if (why != nullptr) {
            *why = reason;
        }
        return std::nullopt;
    };
    const std::filesystem::path path = pathFor(key);
    std::error_code ec;
    const uintmax_t fileSize = std::filesystem::file_size(path, ec);
    if (ec) {
        return fail("no file");
    }
    if (fileSize < kHeaderSize) {
        return fail("truncated header (" + std::to_string(fileSize) + " bytes)");
    }
    std::ifstream file(path, std::ios::binary);
    char header[kHeaderSize];
    if (!file.read(header, kHeaderSize)) {
        return fail("unreadable header");
    }
    if (std::memcmp(header, kMagic, sizeof(kMagic)) != 0) {
        return fail("bad magic");
    }
    Reader r(header + sizeof(kMagic));
    const uint32_t version = r.get<uint32_t>();
    if (version != kSdfCacheFormatVersion) {
        return fail("format version " + std::to_string(version) + ", expected " +
                    std::to_string(kSdfCacheFormatVersion));
    }
    if (r.get<uint64_t>() != key) {
        return fail("key mismatch");
    }
    MeshSdf sdf;
    for (int a = 0; a < 3; ++a) {
        sdf.dims[a] = r.get<uint32_t>();
    }
    sdf.voxelSize = r.get<float>();
    for (int a = 0; a < 3; ++a) {
        sdf.volumeMin[a] = r.get<float>();
    }
    sdf.stats.triangles = r.get<uint32_t>();
    for (int a = 0; a < 3; ++a) {
        sdf.meshBounds.min[a] = r.get<float>();
    }
    for (int a = 0; a < 3; ++a) {
        sdf.meshBounds.max[a] = r.get<float>();
    }
    const uint64_t payloadBytes = r.get<uint64_t>();
    const uint64_t payloadHash = r.get<uint64_t>();
    const double buildSeconds = r.get<double>();
    if (sdf.dims.x == 0 || sdf.dims.y == 0 || sdf.dims.z == 0 || sdf.dims.x > kMaxCachedDim ||
        sdf.dims.y > kMaxCachedDim || sdf.dims.z > kMaxCachedDim) {
        return fail("bad dims");
    }
    if (!(sdf.voxelSize > 0.0f) || !std::isfinite(sdf.voxelSize) || !std::isfinite(sdf.volumeMin.x) ||
        !std::isfinite(sdf.volumeMin.y) || !std::isfinite(sdf.volumeMin.z)) {
        return fail("bad volume");
    }
    const uint64_t voxels = uint64_t(sdf.dims.x) * sdf.dims.y * sdf.dims.z;
    if (payloadBytes != voxels * sizeof(float) || fileSize != kHeaderSize + payloadBytes) {
        return fail("size mismatch (" + std::to_string(fileSize) + " bytes for " + std::to_string(voxels) +
                    " voxels)");
    }
    sdf.distances.resize(voxels);
    if (!file.read(reinterpret_cast<char*>(sdf.distances.data()), std::streamsize(payloadBytes))) {
        return fail("unreadable payload");
    }
    if (fnv1a64(sdf.distances.data(), payloadBytes) != payloadHash) {
        return fail("payload hash mismatch");
    }
    sdf.stats.seconds = buildSeconds;
    sdf.stats.fromCache = true;
    return sdf;
}

bool SdfCache::store(uint64_t key, const MeshSdf& sdf, std::string* why) const {
    auto fail = [&](const std::string& reason) {
        if (why != nullptr) {
            *why = reason;
        }
        return false;
    };
    Writer w;
    w.bytes.insert(w.bytes.end(), kMagic, kMagic + sizeof(kMagic));
    w.put(kSdfCacheFormatVersion);
    w.put(key);
    w.put(sdf.dims.x);
    w.put(sdf.dims.y);
    w.put(sdf.dims.z);
    w.put(sdf.voxelSize);
    w.put(sdf.volumeMin.x);
    w.put(sdf.volumeMin.y);
    w.put(sdf.volumeMin.z);
    w.put(sdf.stats.triangles);
    for (int a = 0; a < 3; ++a) {
        w.put(sdf.meshBounds.min[a]);
    }
    for (int a = 0; a < 3; ++a) {
        w.put(sdf.meshBounds.max[a]);
    }
    const uint64_t payloadBytes = sdf.distances.size() * sizeof(float);
    w.put(payloadBytes);
    w.put(fnv1a64(sdf.distances.data(), payloadBytes));
    w.put(sdf.stats.seconds);
    if (w.bytes.size() != kHeaderSize) {
        return fail("internal: header is " + std::to_string(w.bytes.size()) + " bytes");
    }

    std::error_code ec;
    std::filesystem::create_directories(directory_, ec);
    if (ec) {
        return fail("cannot create " + directory_.string() + ": " + ec.message());
    }
    const std::filesystem::path path = pathFor(key);
    // Unique per process and call, so that concurrent writers never share a temporary.
    static std::atomic<uint64_t> counter{0};
    std::filesystem::path temp = path;
    temp += ".tmp" + std::to_string(uint64_t(std::chrono::steady_clock::now().time_since_epoch().count())) +
            "." + std::to_string(counter++);
    {
        std::ofstream file(temp, std::ios::binary | std::ios::trunc);
        file.write(w.bytes.data(), std::streamsize(w.bytes.size()));
        file.write(reinterpret_cast<const char*>(sdf.distances.data()), std::streamsize(payloadBytes));
        if (!file) {
            file.close();
            std::filesystem::remove(temp, ec);
            return fail("cannot write " + temp.string());
        }
    }
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        return fail("cannot rename into " + path.string());
    }
    return true;
}

MeshSdf SdfCache::getOrBuild(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                             const SdfSettings& settings, SdfCacheReport* report) {
    const auto start = std::chrono::steady_clock::now();
    validate(settings);
    const uint64_t k = key(positions, indices, settings);
    SdfCacheReport local;
    SdfCacheReport& r = report != nullptr ? *report : local;
    r = {};
    r.file = pathFor(k);
    std::optional<MeshSdf> cached = load(k, &r.note);
    if (cached) {
        r.fromCache = true;
        r.note.clear();
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return std::move(*cached);
    }
    MeshSdf sdf = buildMeshSdf(positions, indices, settings);
    std::string storeError;
    if (!store(k, sdf, &storeError)) {
        r.note += "; not stored: " + storeError;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return sdf;
}

} // namespace lumina::sdf
