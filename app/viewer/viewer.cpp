#include "app/viewer/viewer.h"

#include "app/cli.h"
#include "app/viewer/screenshot.h"
#include "rhi/error.h"
#include "rhi/out_of_memory_error.h"
#include "rhi/transfer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
// Debian puts the GLFW platform backend under backends/ of its include directory, vcpkg beside imgui.h.
#if __has_include(<backends/imgui_impl_glfw.h>)
#include <backends/imgui_impl_glfw.h>
#else
#include <imgui_impl_glfw.h>
#endif

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace lumina::app::viewer {

namespace {

// Radians of turn per pixel of mouse movement while looking around.
constexpr float kLookRadiansPerPixel = 0.003f;
// Samples kept for the frame-time graph.
constexpr size_t kGraphFrames = 240;
constexpr std::array<float, 4> kLetterboxColor = {0.02f, 0.02f, 0.02f, 1.0f};

uint64_t allocated(rhi::IDevice& device) {
    return device.allocatedMemoryBytes();
}

} // namespace

Viewer::Viewer(rhi::IDevice& device, const ViewerOptions& options, scene::Scene scene,
               std::optional<std::filesystem::path> settingsPath)
    : device_(device), options_(options), scene_(std::move(scene)),
      window_("lumina-viewer: " + scene_.name, scene_.image.width, scene_.image.height),
      shaders_(std::make_unique<rhi::ShaderLibrary>(device)),
      pipelines_(std::make_unique<gi::PipelineCache>(device, *shaders_)),
      settingsPath_(std::move(settingsPath)),
      camera_(options.camera.value_or(scene_.camera), scene_.worldBounds()), edits_(scene_) {
    sceneBounds_ = scene_.worldBounds();
    sceneDiagonal_ = sceneBounds_.empty() ? 1.0f : glm::length(sceneBounds_.max - sceneBounds_.min);
    state_.slice.position = sceneBounds_.empty() ? 0.0f : 0.5f * (sceneBounds_.min.z + sceneBounds_.max.z);
    state_.technique = options.technique.empty()
                           ? (scene_.technique.empty() ? gi::kDefaultTechnique : scene_.technique)
                           : options.technique;
    state_.preset = options.preset.empty() ? (scene_.preset.empty() ? gi::kDefaultPreset : scene_.preset)
                                           : options.preset;
    state_.exposureEv = options.exposureEv;
    state_.vsync = options.vsync;

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini left in the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOther(window_.handle(), true);

    const uint64_t beforeScene = allocated(device_);
    gpuScene_ = std::make_unique<gi::GpuScene>(device_, scene_);
    memory_.scene = allocated(device_) - beforeScene;
    buildRenderer();
    std::cout << "technique: " << state_.technique << ", preset " << state_.preset << ", exposure "
              << state_.exposureEv << " EV" << std::endl;

    const uint64_t beforeViewer = allocated(device_);
    ui_ = std::make_unique<UiRenderer>(device_);
    swapchain_ = device_.createSwapchain({.window = window_.native(),
                                          .width = window_.framebufferWidth(),
                                          .height = window_.framebufferHeight(),
                                          .vsync = state_.vsync,
                                          .framesInFlight = options.framesInFlight});
    resizeIfNeeded();
    memory_.viewer = allocated(device_) - beforeViewer;
    pendingView_ = options.view; // chosen once the first frame has completed the list
    pendingViewOptional_ = options.viewFromSettings;
    startHotReload();
    inFlight_.resize(options.framesInFlight);
    for (InFlight& slot : inFlight_) {
        slot.commands = device_.createCommandList();
    }
}

Viewer::~Viewer() {
    try {
        device_.waitIdle();
    } catch (const rhi::Error&) {
        // A lost device: nothing left to wait for (run() has reported it), and destructors must
        // not throw.
    }
    ui_.reset();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void Viewer::selectView(const std::string& name) {
    const auto it = std::find_if(state_.views.begin(), state_.views.end(),
                                 [&](const BufferView& view) { return view.name == name; });
    if (it == state_.views.end()) {
        std::string names;
        for (const BufferView& view : state_.views) {
            names += "\n  " + view.name;
        }
        throw UsageError("--view '" + name + "': no such view for this technique; the views are:" + names);
    }
    state_.view = size_t(it - state_.views.begin());
}

// The watcher on shaders/ of the source tree, compiling into the build's shader folder; with
// --test-hot-reload, on copies of both, and the kernels loaded from the copy.
void Viewer::startHotReload() {
    const bool spirv = device_.capabilities().shaderFormat == rhi::ShaderFormat::Spirv;
    std::optional<KernelCompiler> compiler;
    if (options_.hotReload && spirv) {
        compiler = buildKernelCompiler(shaders_->directory());
    }
    if (!options_.testHotReload.empty()) {
        if (!compiler) {
            throw std::runtime_error(
                "--test-hot-reload: this build has no shader hot reload (it needs SPIR-V "
                "kernels compiled with glslang and the source tree's shaders/)");
        }
        hotReloadTest_ = std::make_unique<HotReloadTest>(options_.testHotReload, compiler->sourceRoot,
                                                         shaders_->directory());
        pipelines_.reset();
        shaders_ = std::make_unique<rhi::ShaderLibrary>(device_, hotReloadTest_->spirv());
        pipelines_ = std::make_unique<gi::PipelineCache>(device_, *shaders_);
        compiler->sourceRoot = hotReloadTest_->sources();
        compiler->outputRoot = hotReloadTest_->spirv();
        pendingView_ = HotReloadTest::kView;
    }
    if (compiler) {
        std::cout << "hot reload: watching " << compiler->sourceRoot.string() << '\n';
        hotReload_ = std::make_unique<ShaderHotReload>(std::move(*compiler));
    }
}

void Viewer::buildRenderer() {
    gi::FrameRendererSettings settings;
    const gi::Preset* preset = nullptr;
    try {
        settings.technique = gi::parseGiTechnique(state_.technique);
        preset = &gi::findPreset(state_.preset);
        if (settings.technique == gi::GiTechnique::Lumen) {
            settings.lumen = gi::lumenPreset(*preset, scene_);
        }
        if (settings.technique == gi::GiTechnique::Ddgi) {
            settings.ddgi = gi::ddgiPreset(*preset, scene_);
        }
        if (settings.technique == gi::GiTechnique::ShGrid) {
            settings.shGrid = gi::shGridPreset(*preset, scene_);
        }
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    // The preset's shadow maps, as lumina render uses them (one table, gi/frame/preset.h).
    settings.deferred = {.width = scene_.image.width,
                         .height = scene_.image.height,
                         .sunShadowSize = preset->sunShadowSize,
                         .pointShadowSize = preset->pointShadowSize,
                         .exposureEv = state_.exposureEv,
                         .log = [](std::string_view line) { std::cout << "note: " << line << '\n'; }};
    device_.waitIdle();
    renderer_.reset();
    const uint64_t before = allocated(device_);
    renderer_ = std::make_unique<gi::FrameRenderer>(device_, scene_, *gpuScene_, std::move(settings));
    memory_.renderer = allocated(device_) - before;
    memory_.gi = renderer_->gi() ? renderer_->gi()->memory() : std::vector<gi::GiMemoryPart>{};
    renderer_->setCamera(camera_.camera());
    builtTechnique_ = state_.technique;
    builtPreset_ = state_.preset;
    listViews();
    viewsComplete_ = false;
}

// A technique or preset that needs more GPU memory than there is leaves the viewer on the one
// it had, with the reason in the status line, instead of ending it.
void Viewer::rebuildRenderer() {
    try {
        buildRenderer();
        state_.status = "renderer rebuilt: " + state_.technique +
                        (renderer_->gi() ? ", preset " + state_.preset : std::string());
    } catch (const rhi::OutOfMemoryError& e) {
        state_.status = "not enough GPU memory for " + state_.technique + ", preset " + state_.preset + " (" +
                        e.what() + "); back to " + builtTechnique_ + ", preset " + builtPreset_;
        state_.technique = builtTechnique_;
        state_.preset = builtPreset_;
        buildRenderer();
    }
}

ViewerSettings Viewer::currentSettings() const {
    return {.scene = options_.scene,
            .technique = state_.technique,
            .preset = state_.preset,
            .exposureEv = state_.exposureEv,
            .vsync = state_.vsync,
            .view = state_.view < state_.views.size() && state_.view != 0 ? state_.views[state_.view].name
                                                                          : std::string(),
            .camera = camera_.uprightCamera()};
}

void Viewer::saveSettings() {
    if (!settingsPath_) {
        return;
    }
    try {
        saveViewerSettings(*settingsPath_, currentSettings());
        std::cout << "settings: saved to " << settingsPath_->string() << std::endl;
    } catch (const std::exception& e) {
        std::cerr << "lumina-viewer: " << e.what() << '\n';
    }
}

// The renderer's buffers as the view menu; the same buffer stays on screen when the list still
// has it. Some exist only once a frame has run (the shadow maps of the lights found then), so
// the list is made again after a new renderer's first frame.
void Viewer::listViews() {
    const std::string current = state_.view < state_.views.size() ? state_.views[state_.view].name : "";
    state_.views = listBufferViews(*renderer_, sceneDiagonal_);
    state_.view = 0;
    for (size_t i = 0; i < state_.views.size(); ++i) {
        if (state_.views[i].name == current) {
            state_.view = i;
        }
    }
}

void Viewer::completeViews() {
    listViews();
    viewsComplete_ = true;
    if (!pendingView_.empty()) {
        const bool listed = std::any_of(state_.views.begin(), state_.views.end(),
                                        [&](const BufferView& view) { return view.name == pendingView_; });
        if (listed || !pendingViewOptional_) {
            selectView(pendingView_);
        }
        pendingView_.clear();
    }
    if (!viewsPrinted_) {
        std::cout << "views: " << state_.views.size()
                  << " (the final image and every buffer of the view menu)\n";
        viewsPrinted_ = true;
    }
}

void Viewer::applyEdits() {
    if (state_.rebuildRenderer) {
        state_.rebuildRenderer = false;
        shownImage_.reset(); // it may be the old renderer's
        rebuildRenderer();
        std::cout << state_.status << std::endl;
    }
    // Lights, objects, emission and the animation edit scene_; the renderer recomputes only what
    // changed (a refused edit, say a NaN typed into a field, leaves the frame as it was).
    edits_.animate(scene_);
    try {
        renderer_->applyScene(scene_);
    } catch (const std::exception& e) {
        state_.status = std::string("edit refused: ") + e.what();
    }
    renderer_->deferred().setExposure(state_.exposureEv);
    if (state_.vsync != swapchain_->vsync()) {
        swapchain_->resize(swapchain_->width(), swapchain_->height(), state_.vsync);
    }
}

void Viewer::handleKeys(float seconds) {
    const ImGuiIO& io = ImGui::GetIO();
    FlyInput input;
    input.wheel = float(window_.takeScroll());
    if (io.WantCaptureMouse) {
        input.wheel = 0.0f;
    }
    if (!io.WantCaptureKeyboard) {
        const auto axis = [&](int plus, int minus) {
            return (window_.keyDown(plus) ? 1.0f : 0.0f) - (window_.keyDown(minus) ? 1.0f : 0.0f);
        };
        input.forward = axis(GLFW_KEY_W, GLFW_KEY_S);
        input.right = axis(GLFW_KEY_D, GLFW_KEY_A);
        input.up = axis(GLFW_KEY_E, GLFW_KEY_Q);
        input.fast = window_.keyDown(GLFW_KEY_LEFT_SHIFT) || window_.keyDown(GLFW_KEY_RIGHT_SHIFT);
        if (window_.keyPressed(GLFW_KEY_C)) {
            std::cout << cameraJson(camera_.camera()) << std::endl;
            state_.status = "camera printed to stdout";
        }
        if (window_.keyPressed(GLFW_KEY_F12)) {
            state_.screenshotRequested = true;
        }
        if (window_.keyPressed(GLFW_KEY_F1)) {
            state_.showUi = !state_.showUi;
        }
        if (window_.keyPressed(GLFW_KEY_V)) {
            state_.vsync = !state_.vsync;
        }
        if (window_.keyPressed(GLFW_KEY_RIGHT_BRACKET)) {
            state_.view = (state_.view + 1) % state_.views.size();
        }
        if (window_.keyPressed(GLFW_KEY_LEFT_BRACKET)) {
            state_.view = (state_.view + state_.views.size() - 1) % state_.views.size();
        }
        if (window_.keyPressed(GLFW_KEY_0)) {
            state_.view = 0;
        }
        if (window_.keyPressed(GLFW_KEY_ESCAPE)) {
            window_.requestClose();
        }
    }
    double x = 0, y = 0;
    window_.cursorPosition(x, y);
    const bool rightDown = window_.mouseButtonDown(GLFW_MOUSE_BUTTON_RIGHT);
    if (rightDown && !looking_ && !io.WantCaptureMouse) {
        looking_ = true;
    } else if (!rightDown) {
        looking_ = false;
    }
    if (looking_) {
        input.turnRight = float(x - lastCursorX_) * kLookRadiansPerPixel;
        input.turnUp = -float(y - lastCursorY_) * kLookRadiansPerPixel;
    }
    lastCursorX_ = x;
    lastCursorY_ = y;
    if (camera_.update(input, seconds)) {
        renderer_->setCamera(camera_.camera());
    }
}

void Viewer::resizeIfNeeded() {
    uint32_t width = window_.framebufferWidth();
    uint32_t height = window_.framebufferHeight();
    if (forcedMinimise_) {
        width = height = 0;
    }
    if (width != swapchain_->width() || height != swapchain_->height()) {
        swapchain_->resize(width, height, state_.vsync);
        std::cout << "swapchain: " << swapchain_->width() << "x" << swapchain_->height() << '\n';
    }
    // The surface has the last word on the size (0 x 0 while the window manager minimises it,
    // even when GLFW still reports the old framebuffer size).
    minimised_ = swapchain_->width() == 0 || swapchain_->height() == 0;
    if (minimised_) {
        backbuffer_.reset();
        return;
    }
    if (!backbuffer_ || backbuffer_->desc().width != swapchain_->width() ||
        backbuffer_->desc().height != swapchain_->height()) {
        backbuffer_ =
            device_.createTexture({.format = rhi::Format::RGBA8_UNORM,
                                   .width = swapchain_->width(),
                                   .height = swapchain_->height(),
                                   .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                   .debugName = "viewer: backbuffer"});
    }
}

// --test-resize: grow, shrink, minimise and restore the window over the first frames, so the
// swapchain is recreated at several sizes and survives 0 x 0. Without a window manager (Xvfb)
// nothing iconifies a window, so the minimise is also forced on the viewer's side for 3 frames.
void Viewer::scriptedWindowSteps(uint64_t frame) {
    const uint32_t width = scene_.image.width, height = scene_.image.height;
    switch (frame) {
    case 2:
        window_.setSize(width + width / 2, height + 17);
        break;
    case 4:
        window_.setSize(width / 2 + 3, height / 2 + 5);
        break;
    case 6:
        window_.iconify();
        forcedMinimise_ = true;
        break;
    case 9:
        forcedMinimise_ = false;
        window_.restore();
        window_.setSize(width, height);
        break;
    default:
        break;
    }
    if (frame >= 2 && frame <= 10) {
        // Let the X server apply the size before the swapchain asks the surface for it.
        glfwWaitEventsTimeout(0.05);
    }
}

// --test-edits: what a user does in the panels, scripted: the technique switched to direct and
// back to lumen with another preset (each a renderer rebuild), the first light made brighter
// and moved, and the slice views' axis set to x and then y (through the scene's middle), so
// those paths run under validation.
void Viewer::scriptedEdits(uint64_t frame) {
    switch (frame) {
    case 3:
        state_.technique = "direct";
        state_.rebuildRenderer = true;
        break;
    case 6:
        state_.technique = "lumen";
        state_.preset = "low";
        state_.rebuildRenderer = true;
        break;
    case 9:
        if (!scene_.lights.empty()) {
            scene::Light& light = scene_.lights.front();
            light.intensity *= 2.0f;
            light.position += 0.05f * sceneDiagonal_ * camera_.camera().right();
            light.direction = glm::normalize(light.direction + glm::vec3(0.1f, 0.0f, 0.0f));
        }
        break;
    case 10:
        // An object moves and turns: its SDF bricks, cards and history are redone under validation.
        if (!scene_.instances.empty()) {
            edits_.placeInstance(scene_, uint32_t(scene_.instances.size() - 1),
                                 glm::vec3(0.02f * sceneDiagonal_), 15.0f);
        }
        break;
    case 12:
    case 24: {
        const uint32_t axis = frame == 12 ? LUMINA_VISUALISE_AXIS_X : LUMINA_VISUALISE_AXIS_Y;
        state_.slice.axis = axis;
        state_.slice.position =
            sceneBounds_.empty() ? 0.0f : 0.5f * (sceneBounds_.min[axis] + sceneBounds_.max[axis]);
        std::cout << "slice axis: "
                  << "xyz"[axis] << std::endl;
        break;
    }
    default:
        break;
    }
}

void Viewer::recordFrame(rhi::ICommandList& commands, uint64_t frameIndex,
                         std::vector<gi::SkippedPass>& skipped) {
    gi::FrameContext frame(*pipelines_, commands, frameIndex);
    renderer_->render(frame);
    if (backbuffer_) {
        const ViewSettings settings{
            .exposureScale = std::exp2(state_.exposureEv), .slice = state_.slice, .camera = camera_.camera()};
        const rhi::TextureHandle image =
            visualiser_.record(frame, *renderer_, state_.views[state_.view], settings);
        shownImage_ = image;
        commands.clearColor(*backbuffer_, kLetterboxColor);
        ui_->beginFrame();
        buildUi(image);
        ui_->record(commands, *pipelines_, *ImGui::GetDrawData(), backbuffer_);
        commands.transition(*backbuffer_, rhi::ResourceState::CopySource);
    }
    skipped = frame.skipped();
}

void Viewer::reloadShaders() {
    if (!hotReload_ || !hotReload_->poll()) {
        if (hotReload_ && !hotReload_->error().empty() && state_.shaderError != hotReload_->error()) {
            state_.shaderError = hotReload_->error();
            state_.status = hotReload_->message();
            std::cerr << "hot reload: " << state_.shaderError << '\n';
        }
        return;
    }
    // The frames in flight still use the old pipelines; they are released with them.
    device_.waitIdle();
    pipelines_.reset();
    shaders_ = std::make_unique<rhi::ShaderLibrary>(device_, shaders_->directory());
    pipelines_ = std::make_unique<gi::PipelineCache>(device_, *shaders_);
    state_.shaderError.clear();
    state_.status = hotReload_->message();
    ++reloads_;
    std::cout << "hot reload: " << state_.status << std::endl;
}

void Viewer::takeScreenshot(const std::filesystem::path& path) {
    if (options_.screenshotWindow && backbuffer_) {
        writeWindowScreenshot(device_, *backbuffer_, path);
    } else {
        writeScreenshot(device_, *renderer_, shownImage_ ? *shownImage_ : *renderer_->deferred().ldr(), path);
    }
    state_.status = "wrote " + path.string();
    std::cout << state_.status << std::endl;
}

int Viewer::run() {
    int code = 0;
    try {
        code = runFrames();
    } catch (const rhi::DeviceLostError&) {
        saveSettings();
        throw;
    } catch (const rhi::OutOfMemoryError&) {
        saveSettings();
        throw;
    }
    saveSettings();
    return code;
}

int Viewer::runFrames() {
    rhi::IQueue& queue = device_.queue(rhi::QueueType::Graphics);
    const uint64_t lastFrame =
        options_.screenshotAfter ? *options_.screenshotAfter : options_.common.frames.value_or(0);
    auto previous = std::chrono::steady_clock::now();
    uint64_t frame = 0;
    while (!window_.shouldClose()) {
        window_.pollEvents();
        if (options_.testResize) {
            scriptedWindowSteps(frame);
        }
        if (options_.testEdits) {
            scriptedEdits(frame);
        }
        resizeIfNeeded();
        if (minimised_ && !forcedMinimise_) {
            window_.waitEvents(); // nothing to show: sleep until the window comes back
            continue;
        }
        const auto now = std::chrono::steady_clock::now();
        const float seconds = std::chrono::duration<float>(now - previous).count();
        previous = now;
        if (!minimised_) {
            ImGui_ImplGlfw_NewFrame();
        }
        handleKeys(seconds);
        applyEdits();
        reloadShaders();
        if (options_.cycleViews) {
            state_.view = frame % state_.views.size();
            std::cout << "view: " << state_.views[state_.view].name << '\n';
        }

        InFlight& slot = inFlight_[frame % inFlight_.size()];
        if (slot.fenceValue != 0) {
            queue.waitForValue(slot.fenceValue);
            state_.timers = slot.commands->timerResults();
            state_.skipped = slot.skipped;
            if (!state_.timers.empty()) {
                // From the first pass's start to the last one's end: timers nest, so no sum.
                uint64_t begin = UINT64_MAX, end = 0;
                for (const rhi::TimerResult& timer : state_.timers) {
                    begin = std::min(begin, timer.beginTicks);
                    end = std::max(end, timer.endTicks);
                }
                const double ns = double(end - begin) * device_.capabilities().timestampPeriodNs;
                state_.gpuMs.push_back(float(ns * 1e-6));
            }
        }
        state_.frameMs.push_back(seconds * 1000.0f);
        while (state_.frameMs.size() > kGraphFrames) {
            state_.frameMs.pop_front();
        }
        while (state_.gpuMs.size() > kGraphFrames) {
            state_.gpuMs.pop_front();
        }

        slot.commands->begin();
        recordFrame(*slot.commands, frame, slot.skipped);
        if (!viewsComplete_) {
            completeViews();
        }
        slot.commands->end();
        slot.fenceValue = queue.submit(*slot.commands);
        if (backbuffer_ && swapchain_->present(*backbuffer_) == rhi::PresentResult::Suboptimal) {
            swapchain_->resize(window_.framebufferWidth(), window_.framebufferHeight(), state_.vsync);
        }
        ++frame;
        if (state_.screenshotRequested) {
            state_.screenshotRequested = false;
            const std::string name = "lumina-viewer-" + std::to_string(++screenshotCount_);
            takeScreenshot(name + ".png");
            if (!options_.screenshotWindow) {
                takeScreenshot(name + ".exr");
            }
        }
        if (lastFrame != 0 && frame >= lastFrame) {
            break;
        }
        const auto readShown = [&] {
            device_.waitIdle();
            return rhi::readTexture(device_, *shownImage_);
        };
        if (hotReloadTest_ && shownImage_ &&
            hotReloadTest_->afterFrame(readShown, reloads_, hotReload_->error())) {
            break;
        }
    }
    device_.waitIdle();
    if (options_.screenshotAfter) {
        takeScreenshot(options_.screenshotPath);
    }
    std::cout << "frames: " << frame << '\n';
    if (device_.validationMessageCount() != 0) {
        std::cerr << "lumina-viewer: " << device_.validationMessageCount() << " validation message(s)\n";
        return 1;
    }
    return 0;
}

} // namespace lumina::app::viewer
