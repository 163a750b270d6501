#pragma once
// The viewer's window: GLFW with no client API (the RHI presents through its own swapchain),
// its native handle for rhi::NativeWindow, its framebuffer size and what the user pressed.
#include "rhi/swapchain.h"

#include <cstdint>
#include <string>

struct GLFWwindow;

namespace lumina::app::viewer {

class GlfwWindow {
public:
    // Throws std::runtime_error with GLFW's description when there is no display or no window.
    GlfwWindow(const std::string& title, uint32_t width, uint32_t height);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    rhi::NativeWindow native() const;
    bool shouldClose() const;
    void requestClose();
    void pollEvents();
    // Blocks until an event comes (while minimised nothing is drawn).
    void waitEvents();

    // In pixels; 0 x 0 while minimised.
    uint32_t framebufferWidth() const;
    uint32_t framebufferHeight() const;
    void setSize(uint32_t width, uint32_t height);
    void iconify();
    void restore();

    bool keyDown(int key) const;
    // True once per press: the key is down now and was not at the last call for it.
    bool keyPressed(int key);
    bool mouseButtonDown(int button) const;
    void cursorPosition(double& x, double& y) const;
    // Wheel movement since the last call.
    double takeScroll();

private:
    GLFWwindow* window_ = nullptr;
    bool previousKeys_[512] = {};
    double scroll_ = 0.0;
};

} // namespace lumina::app::viewer
