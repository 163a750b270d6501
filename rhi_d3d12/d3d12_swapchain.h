#pragma once
// rhi::ISwapchain on D3D12: a DXGI flip-model swapchain (FLIP_DISCARD) on the window's HWND,
// whose buffers only ever receive a copy of the application's frame (rhi/swapchain.h). Per
// frame in flight: a command allocator and the fence value its copy signals. vsync off presents
// with ALLOW_TEARING where DXGI supports it. A minimised (0 x 0) window skips presents: DXGI
// buffers cannot be resized to zero.
#include "rhi/swapchain.h"
#include "rhi_d3d12/d3d12_context.h"
#include "rhi_d3d12/d3d12_state.h"

#include <memory>
#include <vector>

namespace lumina::d3d12 {

class Queue;

class Swapchain final : public rhi::ISwapchain {
public:
    Swapchain(ContextHandle context, Queue& queue, const rhi::SwapchainDesc& desc);
    ~Swapchain() override;
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    uint32_t width() const override { return width_; }
    uint32_t height() const override { return height_; }
    bool vsync() const override { return vsync_; }
    void resize(uint32_t width, uint32_t height, bool vsync) override;
    rhi::PresentResult present(rhi::ITexture& image) override;

private:
    struct FrameSlot {
        ComPtr<ID3D12CommandAllocator> allocator;
        uint64_t fenceValue = 0;
        std::shared_ptr<NativeResource> source; // kept alive until fenceValue is reached
    };

    void getBuffers();
    void waitForPresents();
    void recordCopy(ID3D12Resource* source, ID3D12Resource* target);

    ContextHandle context_;
    Queue& queue_;
    bool vsync_ = true;
    bool tearingSupported_ = false;
    uint32_t width_ = 0; // 0 while minimised
    uint32_t height_ = 0;
    ComPtr<IDXGISwapChain3> swapchain_;
    std::vector<ComPtr<ID3D12Resource>> buffers_;
    ComPtr<ID3D12GraphicsCommandList> commands_;
    ComPtr<ID3D12Fence> fence_;
    uint64_t lastFenceValue_ = 0;
    std::vector<FrameSlot> slots_;
    uint64_t frame_ = 0;
};

} // namespace lumina::d3d12
