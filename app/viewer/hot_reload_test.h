#pragma once
// --test-hot-reload DIR: shader hot reload checked end to end while the viewer runs. The viewer
// loads its kernels from a copy of the build's SPIR-V and watches a copy of the HLSL sources,
// both under DIR (so the build's own kernels are never touched), and shows kView. Then:
//   1. after kWarmUpFrames frames, the kernel behind kView (shaders/viewer/visualise.hlsl, main)
//      is edited to invert its colours; the first frame after the reload must show exactly the
//      inverted image (each RGB byte 255 minus the old one, within 1 for rounding);
//   2. a syntax error is added to the kernel; the compiler's error must name the file, and the
//      next frames must show the inverted image unchanged (the old kernel keeps running), with no
//      kernel replaced.
// A step that does not happen within kStepTimeout fails the test; failures throw, so the viewer
// exits 1.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lumina::app::viewer {

class HotReloadTest {
public:
    static constexpr const char* kView = "gbuffer: albedo";
    static constexpr const char* kKernel = "viewer/visualise.hlsl";

    // Copies `sources` (shaders/ of the source tree) to DIR/src and `spirv` (the build's shader
    // folder) to DIR/spv, replacing what was there.
    HotReloadTest(const std::filesystem::path& directory, const std::filesystem::path& sources,
                  const std::filesystem::path& spirv);

    const std::filesystem::path& sources() const { return sources_; }
    const std::filesystem::path& spirv() const { return spirv_; }

    // After each frame's submission. `readImage` waits for the GPU and reads back the image on
    // screen (RGBA8); `reloads` counts the reloads so far; `error` is the hot reload's last
    // compile error (empty after a success). True once the test has passed.
    bool afterFrame(const std::function<std::vector<uint8_t>()>& readImage, uint32_t reloads,
                    const std::string& error);

private:
    enum class Step { WarmUp, WaitForReload, WaitForError, Done };

    void startStep(Step step);
    void checkTimeout() const;

    std::filesystem::path sources_, spirv_;
    std::string original_; // the kernel's source as the build has it
    std::string edited_;   // with its colours inverted
    Step step_ = Step::WarmUp;
    uint32_t frames_ = 0;
    uint32_t reloadsBefore_ = 0;
    uint32_t framesAfterError_ = 0;
    std::chrono::steady_clock::time_point stepStart_;
    std::vector<uint8_t> before_;   // the image before the edit
    std::vector<uint8_t> inverted_; // the image after it
};

} // namespace lumina::app::viewer
