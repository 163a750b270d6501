#include "app/viewer/glfw_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#if defined(_WIN32)
#define GLFW_EXPOSE_NATIVE_WIN32
#else
#define GLFW_EXPOSE_NATIVE_X11
#endif
#include <GLFW/glfw3native.h>
#include <stdexcept>

namespace lumina::app::viewer {

namespace {

std::string glfwErrorText() {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    return code == GLFW_NO_ERROR ? "no error reported"
                                 : std::string(description ? description : "unknown") + " (GLFW error " +
                                       std::to_string(code) + ")";
}

} // namespace

GlfwWindow::GlfwWindow(const std::string& title, uint32_t width, uint32_t height) {
    if (!glfwInit()) {
        throw std::runtime_error("cannot open a window: " + glfwErrorText() +
                                 " (no display? on a headless machine run under xvfb-run -a)");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string error = glfwErrorText();
        glfwTerminate();
        throw std::runtime_error("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                                 " window: " + error);
    }
    glfwSetWindowUserPointer(window_, this);
    // Chained before ImGui installs its callbacks, which call the previous one.
    glfwSetScrollCallback(window_, [](GLFWwindow* window, double, double y) {
        static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window))->scroll_ += y;
    });
}

GlfwWindow::~GlfwWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

rhi::NativeWindow GlfwWindow::native() const {
    rhi::NativeWindow native;
#if defined(_WIN32)
    native.platform = rhi::NativeWindow::Platform::Win32;
    native.window = reinterpret_cast<uint64_t>(glfwGetWin32Window(window_));
#else
    native.platform = rhi::NativeWindow::Platform::Xlib;
    native.display = glfwGetX11Display();
    native.window = static_cast<uint64_t>(glfwGetX11Window(window_));
#endif
    return native;
}

bool GlfwWindow::shouldClose() const {
    return glfwWindowShouldClose(window_);
}

void GlfwWindow::requestClose() {
    glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void GlfwWindow::pollEvents() {
    glfwPollEvents();
}

void GlfwWindow::waitEvents() {
    glfwWaitEventsTimeout(0.1);
}

uint32_t GlfwWindow::framebufferWidth() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) ? 0u : uint32_t(width);
}

uint32_t GlfwWindow::framebufferHeight() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) ? 0u : uint32_t(height);
}

void GlfwWindow::setSize(uint32_t width, uint32_t height) {
    glfwSetWindowSize(window_, int(width), int(height));
}

void GlfwWindow::iconify() {
    glfwIconifyWindow(window_);
}

void GlfwWindow::restore() {
    glfwRestoreWindow(window_);
}

bool GlfwWindow::keyDown(int key) const {
    return glfwGetKey(window_, key) == GLFW_PRESS;
}

bool GlfwWindow::keyPressed(int key) {
    const bool down = keyDown(key);
    bool& previous = previousKeys_[key & 511];
    const bool pressed = down && !previous;
    previous = down;
    return pressed;
}

bool GlfwWindow::mouseButtonDown(int button) const {
    return glfwGetMouseButton(window_, button) == GLFW_PRESS;
}

void GlfwWindow::cursorPosition(double& x, double& y) const {
    glfwGetCursorPos(window_, &x, &y);
}

double GlfwWindow::takeScroll() {
    const double scroll = scroll_;
    scroll_ = 0.0;
    return scroll;
}

} // namespace lumina::app::viewer
