#include "gi/sdf/sdf_cache.h"
#include "tests/bvh/test_meshes.h"
#include "tests/test_env.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>

namespace lumina::sdf {
namespace {

using lumina::testing::setEnv;

class SdfCacheTest : public ::testing::Test {
protected:
    void SetUp() override {
        directory =
            std::filesystem::temp_directory_path() /
            ("lumina_sdf_cache_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
             "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(directory);
        mesh = lumina::test::makeIcosphere({0, 0, 0}, 1.0f, 3);
        settings.resolution = 32;
    }
    void TearDown() override { std::filesystem::remove_all(directory); }

    std::filesystem::path directory;
    lumina::test::Mesh mesh;
    SdfSettings settings;
};

TEST_F(SdfCacheTest, SecondBuildLoadsTheSameData) {
    SdfCache cache(directory);
    SdfCacheReport first, second;
    const MeshSdf built = cache.getOrBuild(mesh.positions, mesh.indices, settings, &first);
    EXPECT_FALSE(first.fromCache);
    EXPECT_EQ(first.note, "no file");
    EXPECT_TRUE(std::filesystem::exists(first.file));
    EXPECT_NE(first.summary(built).find("built in"), std::string::npos);

    const MeshSdf loaded = cache.getOrBuild(mesh.positions, mesh.indices, settings, &second);
    EXPECT_TRUE(second.fromCache) << second.note;
    EXPECT_TRUE(loaded.stats.fromCache);
    EXPECT_LT(second.seconds, first.seconds);
    EXPECT_NE(second.summary(loaded).find("loaded from cache"), std::string::npos);
    EXPECT_EQ(loaded.dims, built.dims);
    EXPECT_EQ(loaded.volumeMin, built.volumeMin);
    EXPECT_EQ(loaded.voxelSize, built.voxelSize);
    EXPECT_EQ(loaded.meshBounds.min, built.meshBounds.min);
    EXPECT_EQ(loaded.meshBounds.max, built.meshBounds.max);
    EXPECT_EQ(loaded.stats.triangles, built.stats.triangles);
    ASSERT_EQ(loaded.distances.size(), built.distances.size());
    EXPECT_EQ(0, std::memcmp(loaded.distances.data(), built.distances.data(), built.distances.size() * 4));
}

TEST_F(SdfCacheTest, KeyDependsOnGeometryAndSettings) {
    const uint64_t base = SdfCache::key(mesh.positions, mesh.indices, settings);
    EXPECT_EQ(base, SdfCache::key(mesh.positions, mesh.indices, settings));
    SdfSettings other = settings;
    other.threads = 7; // does not change the result, so not the key
    EXPECT_EQ(base, SdfCache::key(mesh.positions, mesh.indices, other));
    other = settings;
    other.resolution = 33;
    EXPECT_NE(base, SdfCache::key(mesh.positions, mesh.indices, other));
    other = settings;
    other.insideFraction = 0.6f;
    EXPECT_NE(base, SdfCache::key(mesh.positions, mesh.indices, other));
    lumina::test::Mesh moved = mesh;
    moved.positions[5].x += 1e-6f;
    EXPECT_NE(base, SdfCache::key(moved.positions, moved.indices, settings));
    lumina::test::Mesh flipped = mesh;
    std::swap(flipped.indices[0], flipped.indices[1]);
    EXPECT_NE(base, SdfCache::key(flipped.positions, flipped.indices, settings));
    EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cull); // the published FNV-1a 64 test vector
}

TEST_F(SdfCacheTest, CorruptFilesAreRebuilt) {
    SdfCache cache(directory);
    SdfCacheReport report;
    const MeshSdf built = cache.getOrBuild(mesh.positions, mesh.indices, settings, &report);
    const std::filesystem::path file = report.file;
    const uintmax_t size = std::filesystem::file_size(file);

    struct Damage {
        const char* name;
        std::function<void()> apply;
        const char* expectedNote;
    };
    auto overwrite = [&](std::streamoff offset, const std::string& bytes) {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(offset);
        f.write(bytes.data(), std::streamsize(bytes.size()));
    };
    auto flipByte = [&](std::streamoff offset) {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(offset);
        char c = 0;
        f.read(&c, 1);
        f.seekp(offset);
        c = char(c ^ 0x10);
        f.write(&c, 1);
    };
    const Damage damages[] = {
        {"truncated payload", [&] { std::filesystem::resize_file(file, size - 7); }, "size mismatch"},
        {"truncated header", [&] { std::filesystem::resize_file(file, 10); }, "truncated header"},
        {"empty", [&] { std::filesystem::resize_file(file, 0); }, "truncated header"},
        {"flipped payload byte", [&] { flipByte(std::streamoff(size - 100)); }, "payload hash mismatch"},
        {"bad magic", [&] { overwrite(0, "XXXX"); }, "bad magic"},
        {"future version", [&] { overwrite(4, std::string("\x63\0\0\0", 4)); }, "format version"},
        {"huge dims", [&] { overwrite(16, std::string("\xFF\xFF\xFF\x7F", 4)); }, "bad dims"},
    };
    for (const Damage& damage : damages) {
        damage.apply();
        SdfCacheReport again;
        const MeshSdf rebuilt = cache.getOrBuild(mesh.positions, mesh.indices, settings, &again);
        EXPECT_FALSE(again.fromCache) << damage.name;
        EXPECT_NE(again.note.find(damage.expectedNote), std::string::npos)
            << damage.name << ": " << again.note;
        ASSERT_EQ(rebuilt.distances, built.distances) << damage.name;
        // ...and the rebuilt file is good again.
        SdfCacheReport after;
        cache.getOrBuild(mesh.positions, mesh.indices, settings, &after);
        EXPECT_TRUE(after.fromCache) << damage.name << ": " << after.note;
    }
}

TEST_F(SdfCacheTest, UnwritableDirectoryStillBuilds) {
    std::filesystem::create_directories(directory);
    const std::filesystem::path blocker = directory / "not_a_directory";
    std::ofstream(blocker) << "x";
    SdfCache cache(blocker / "sdf");
    SdfCacheReport report;
    const MeshSdf sdf = cache.getOrBuild(mesh.positions, mesh.indices, settings, &report);
    EXPECT_FALSE(report.fromCache);
    EXPECT_NE(report.note.find("not stored"), std::string::npos) << report.note;
    EXPECT_FALSE(sdf.distances.empty());
}

TEST_F(SdfCacheTest, DefaultDirectoryFollowsTheEnvironment) {
    const char* old = std::getenv("LUMINA_CACHE_DIR");
    const std::string saved = old != nullptr ? old : "";
    setEnv("LUMINA_CACHE_DIR", "/tmp/lumina_cache_env_test");
    EXPECT_EQ(SdfCache::defaultDirectory(), std::filesystem::path("/tmp/lumina_cache_env_test") / "sdf");
    setEnv("LUMINA_CACHE_DIR", "");
    EXPECT_NE(SdfCache::defaultDirectory().string().find("lumina"), std::string::npos);
    setEnv("LUMINA_CACHE_DIR", saved);
}

} // namespace
} // namespace lumina::sdf
