#pragma once
// The viewer's frame loop: input -> camera and settings -> FrameRenderer -> debug view ->
// UI -> present. One renderer at a time, rebuilt when the technique or preset changes; the
// lights are edited in place (DeferredRenderer::setLights) and the GI follows them.
#include "app/viewer/buffer_views.h"
#include "app/viewer/fly_camera.h"
#include "app/viewer/glfw_window.h"
#include "app/viewer/hot_reload_test.h"
#include "app/viewer/scene_edits.h"
#include "app/viewer/shader_hot_reload.h"
#include "app/viewer/ui_renderer.h"
#include "app/viewer/viewer_options.h"
#include "app/viewer/viewer_settings.h"
#include "gi/core/pipeline_cache.h"
#include "gi/frame/frame_renderer.h"
#include "gi/gpu_scene/gpu_scene.h"
#include "gi/scene/scene.h"

#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lumina::app::viewer {

// What the panels show and edit; the loop applies the edits.
struct ViewerState {
    std::string technique;
    std::string preset;
    float exposureEv = 0.0f;
    bool vsync = true;
    bool showUi = true;
    size_t view = 0; // index into views
    std::vector<BufferView> views;
    SliceSettings slice; // where the SDF and voxel-lighting slices cut
    bool rebuildRenderer = false;
    bool screenshotRequested = false;
    std::string status;        // the last action's message (screenshot written, rebuild failed...)
    std::string shaderError;   // the compiler's output when a saved kernel does not compile
    std::deque<float> frameMs; // CPU frame times, newest last
    std::deque<float> gpuMs;   // GPU time of the frame's passes
    std::vector<rhi::TimerResult> timers;
    std::vector<gi::SkippedPass> skipped;
};

// Bytes per subsystem: the device's allocation counter sampled around each construction.
struct MemoryUse {
    uint64_t scene = 0;
    uint64_t renderer = 0;
    std::vector<gi::GiMemoryPart> gi; // the GI technique's parts (none for direct)
    uint64_t viewer = 0;
    uint64_t device = 0;
};

class Viewer {
public:
    // `settingsPath`: where the settings are saved at exit (none: not saved).
    Viewer(rhi::IDevice& device, const ViewerOptions& options, scene::Scene scene,
           std::optional<std::filesystem::path> settingsPath);
    ~Viewer();
    // Returns the exit code. A lost device or a failed allocation saves the settings first and
    // then throws on (rhi::DeviceLostError, rhi::OutOfMemoryError) for main to report.
    int run();

private:
    struct InFlight {
        rhi::CommandListHandle commands;
        uint64_t fenceValue = 0;
        std::vector<gi::SkippedPass> skipped;
    };

    int runFrames();
    void buildRenderer();
    void rebuildRenderer();
    ViewerSettings currentSettings() const;
    void saveSettings();
    void applyEdits();
    void handleKeys(float seconds);
    void resizeIfNeeded();
    void scriptedWindowSteps(uint64_t frame);
    void scriptedEdits(uint64_t frame);
    void recordFrame(rhi::ICommandList& commands, uint64_t frameIndex, std::vector<gi::SkippedPass>& skipped);
    void buildUi(const rhi::TextureHandle& image);
    void slicePanel(const BufferView& view);
    void takeScreenshot(const std::filesystem::path& path);
    void reloadShaders();
    void startHotReload();
    void selectView(const std::string& name);
    void listViews();
    void completeViews();

    rhi::IDevice& device_;
    ViewerOptions options_;
    scene::Scene scene_;
    scene::Bounds sceneBounds_;
    float sceneDiagonal_ = 1.0f;
    GlfwWindow window_;
    rhi::SwapchainHandle swapchain_;
    rhi::TextureHandle backbuffer_; // what present() copies: RGBA8, the window's size
    bool minimised_ = false;
    bool forcedMinimise_ = false; // --test-resize's minimise, where no window manager iconifies
    // Replaced together when hot reload changes a kernel: the next frame builds new pipelines.
    std::unique_ptr<rhi::ShaderLibrary> shaders_;
    std::unique_ptr<gi::PipelineCache> pipelines_;
    std::unique_ptr<ShaderHotReload> hotReload_;
    uint32_t reloads_ = 0; // kernel reloads so far
    std::unique_ptr<HotReloadTest> hotReloadTest_;
    bool viewsComplete_ = false; // listed after the renderer's first frame
    bool viewsPrinted_ = false;
    std::string pendingView_;          // --view, chosen once the list is complete
    bool pendingViewOptional_ = false; // from the saved settings: skipped when the list lacks it
    std::optional<std::filesystem::path> settingsPath_;
    std::string builtTechnique_, builtPreset_; // the renderer's, for going back after a failed rebuild
    std::unique_ptr<gi::GpuScene> gpuScene_;
    std::unique_ptr<gi::FrameRenderer> renderer_;
    FlyCamera camera_;
    SceneEdits edits_; // after scene_: made from it
    ViewerState state_;
    MemoryUse memory_;
    std::unique_ptr<UiRenderer> ui_;
    Visualiser visualiser_;
    rhi::TextureHandle shownImage_; // the last frame's display image: the composite's or a debug view
    std::vector<InFlight> inFlight_;
    double lastCursorX_ = 0, lastCursorY_ = 0;
    bool looking_ = false;
    uint32_t screenshotCount_ = 0;
};

} // namespace lumina::app::viewer
