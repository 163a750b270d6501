// EXR inputs the fuzzers once failed on (tests/fuzz/regressions/exr_*/), read through
// gi/image/exr.h with whichever library this executable was built on: each must be refused
// with an ImageError naming the file. Under the sanitizer build (.ci/sanitizers.sh) a leak or
// an out-of-bounds access on the way fails the test too.
#include "gi/image/exr.h"

#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace lumina::image {
namespace {

std::vector<std::filesystem::path> regressionInputs() {
    std::vector<std::filesystem::path> inputs;
    const std::filesystem::path root = std::filesystem::path(LUMINA_SOURCE_DIR) / "tests/fuzz/regressions";
    for (const char* fuzzer : {"exr_openexr", "exr_tinyexr"}) {
        if (std::filesystem::is_directory(root / fuzzer)) {
            for (const auto& entry : std::filesystem::directory_iterator(root / fuzzer)) {
                inputs.push_back(entry.path());
            }
        }
    }
    return inputs;
}

TEST(ExrFuzzRegressions, EachInputIsRefusedWithAnErrorNamingTheFile) {
    const std::vector<std::filesystem::path> inputs = regressionInputs();
    ASSERT_FALSE(inputs.empty()) << "no input under tests/fuzz/regressions/exr_*";
    for (const std::filesystem::path& input : inputs) {
        SCOPED_TRACE(input.string());
        // The header may be whole (a file truncated in its pixels): readExrInfo may succeed,
        // but only with an ImageError may it fail.
        try {
            (void)readExrInfo(input);
        } catch (const ImageError&) {
        }
        try {
            (void)readExr(input);
            ADD_FAILURE() << "expected an ImageError";
        } catch (const ImageError& error) {
            EXPECT_NE(std::string(error.what()).find(input.filename().string()), std::string::npos)
                << error.what();
        }
    }
}

} // namespace
} // namespace lumina::image
