// libFuzzer target for the EXR reader (readExrInfo and readExr, gi/image/exr.h): built twice,
// once on OpenEXR (Linux's reader) and once on tinyexr (the MinGW build's, compiled from its
// header here, so the fuzzer sees its branches). Both read from a path, so each input is
// written to a file of this process first. An ImageError is the expected answer to bad
// input; anything else (a crash, a sanitizer report, another exception) is a bug.
#include "gi/image/exr.h"
#include "gi/image/image.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

// The file each input is written to, one per process, removed when the process ends.
struct InputFile {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("lumina_exr_fuzz_" + std::to_string(getpid()) + ".exr");
    ~InputFile() {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
    }
};

const std::filesystem::path& inputPath() {
    static const InputFile file;
    return file.path;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace lumina::image;
    {
        std::ofstream file(inputPath(), std::ios::binary | std::ios::trunc);
        file.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    try {
        (void)readExrInfo(inputPath());
    } catch (const ImageError&) {
    }
    try {
        const Image image = readExr(inputPath());
        if (image.width() == 0 || image.height() == 0) {
            std::abort(); // an image that was read has pixels
        }
    } catch (const ImageError&) {
    }
    return 0;
}
