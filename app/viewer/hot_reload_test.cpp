#include "app/viewer/hot_reload_test.h"

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace lumina::app::viewer {

namespace {

// Frames rendered before the first edit (the GBuffer is complete from the first one).
constexpr uint32_t kWarmUpFrames = 3;
// How long a reload may take: every entry point of the file is compiled and validated, on a
// machine that may be busy.
constexpr std::chrono::seconds kStepTimeout{180};
// The line of the kernel the test edits, and what it becomes: the colours inverted.
constexpr const char* kOutputLine = "gOutput[id.xy] = float4(display(gSource.Load(int3(id.xy, 0))), 1.0);";
constexpr const char* kInvertedLine =
    "gOutput[id.xy] = float4(1.0 - display(gSource.Load(int3(id.xy, 0))), 1.0);";
constexpr const char* kSyntaxError = "\nthis line is not HLSL\n";
// Frames checked after the error is reported: the old kernel keeps running in each.
constexpr uint32_t kFramesAfterError = 3;
// RGBA8 rounding of 1 - x against 255 - round(255 x).
constexpr int kRoundingTolerance = 1;

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error("hot reload test: cannot read " + path.string());
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) {
        throw std::runtime_error("hot reload test: cannot write " + path.string());
    }
}

void copyTree(const std::filesystem::path& from, const std::filesystem::path& to) {
    std::filesystem::remove_all(to);
    std::filesystem::create_directories(to);
    std::filesystem::copy(from, to, std::filesystem::copy_options::recursive);
}

// The first pixel whose RGB is not 255 minus `before`'s, or -1.
int64_t firstNotInverted(const std::vector<uint8_t>& before, const std::vector<uint8_t>& after) {
    for (size_t i = 0; i < before.size(); ++i) {
        if (i % 4 != 3 && std::abs(int(before[i]) + int(after[i]) - 255) > kRoundingTolerance) {
            return int64_t(i / 4);
        }
    }
    return -1;
}

} // namespace

HotReloadTest::HotReloadTest(const std::filesystem::path& directory, const std::filesystem::path& sources,
                             const std::filesystem::path& spirv)
    : sources_(directory / "src"), spirv_(directory / "spv") {
    copyTree(sources, sources_);
    copyTree(spirv, spirv_);
    original_ = readFile(sources_ / kKernel);
    if (original_.find(kOutputLine) == std::string::npos) {
        throw std::runtime_error(std::string("hot reload test: ") + kKernel +
                                 " no longer has the line it edits: " + kOutputLine);
    }
    stepStart_ = std::chrono::steady_clock::now();
}

void HotReloadTest::startStep(Step step) {
    step_ = step;
    stepStart_ = std::chrono::steady_clock::now();
}

void HotReloadTest::checkTimeout() const {
    if (std::chrono::steady_clock::now() - stepStart_ > kStepTimeout) {
        throw std::runtime_error(std::string("hot reload test: ") +
                                 (step_ == Step::WaitForReload
                                      ? "the edited kernel was not reloaded"
                                      : "the kernel's syntax error was not reported") +
                                 " within " + std::to_string(kStepTimeout.count()) + " s");
    }
}

bool HotReloadTest::afterFrame(const std::function<std::vector<uint8_t>()>& readImage, uint32_t reloads,
                               const std::string& error) {
    ++frames_;
    switch (step_) {
    case Step::WarmUp:
        if (frames_ >= kWarmUpFrames) {
            before_ = readImage();
            edited_ = original_;
            edited_.replace(edited_.find(kOutputLine), std::string(kOutputLine).size(), kInvertedLine);
            reloadsBefore_ = reloads;
            writeFile(sources_ / kKernel, edited_);
            std::cout << "hot reload test: edited " << kKernel << " to invert its colours" << std::endl;
            startStep(Step::WaitForReload);
        }
        return false;
    case Step::WaitForReload: {
        if (reloads == reloadsBefore_) {
            checkTimeout();
            return false;
        }
        inverted_ = readImage();
        if (inverted_.size() != before_.size()) {
            throw std::runtime_error("hot reload test: the image changed size across the reload");
        }
        if (const int64_t pixel = firstNotInverted(before_, inverted_); pixel >= 0) {
            throw std::runtime_error("hot reload test: after the reload, pixel " + std::to_string(pixel) +
                                     " is not the inverse of what it was: the edited kernel is not running");
        }
        std::cout << "hot reload test: the reloaded kernel inverted the image" << std::endl;
        writeFile(sources_ / kKernel, edited_ + kSyntaxError);
        startStep(Step::WaitForError);
        return false;
    }
    case Step::WaitForError: {
        if (error.empty()) {
            checkTimeout();
            return false;
        }
        if (error.find(kKernel) == std::string::npos) {
            throw std::runtime_error(std::string("hot reload test: the compile error does not name ") +
                                     kKernel + ":\n" + error);
        }
        if (readImage() != inverted_) {
            throw std::runtime_error(
                "hot reload test: the image changed after a kernel that does not compile was saved");
        }
        if (reloads != reloadsBefore_ + 1) {
            throw std::runtime_error(
                "hot reload test: a kernel that does not compile replaced the running one");
        }
        if (++framesAfterError_ < kFramesAfterError) {
            return false;
        }
        std::cout
            << "hot reload test: the syntax error was reported and the previous kernel kept running for "
            << kFramesAfterError << " frames: passed" << std::endl;
        startStep(Step::Done);
        return true;
    }
    case Step::Done:
        return true;
    }
    return true;
}

} // namespace lumina::app::viewer
