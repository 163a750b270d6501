#include "rhi_d3d12/d3d12_swapchain.h"

#include "rhi/error.h"
#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_queue.h"

#include <algorithm>
#include <string>

namespace lumina::d3d12 {

namespace {

// The frame is display-encoded already (the composite applies the sRGB OETF): a UNORM buffer
// shows it as it is, and matches the RGBA8_UNORM texture present() copies from.
constexpr DXGI_FORMAT kBufferFormat = DXGI_FORMAT_R8G8B8A8_UNORM;

bool tearingSupported(IDXGIFactory4* factory) {
    ComPtr<IDXGIFactory5> factory5;
    BOOL allowed = FALSE;
    return SUCCEEDED(factory->QueryInterface(IID_PPV_ARGS(&factory5))) &&
           SUCCEEDED(factory5->CheckFeatureSupport(DXGI_FEATURE_PRESENT_ALLOW_TEARING, &allowed,
                                                   sizeof(allowed))) &&
           allowed;
}

D3D12_RESOURCE_BARRIER transition(ID3D12Resource* resource, D3D12_RESOURCE_STATES before,
                                  D3D12_RESOURCE_STATES after) {
    D3D12_RESOURCE_BARRIER barrier{};
    barrier.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
    barrier.Transition.pResource = resource;
    barrier.Transition.Subresource = D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES;
    barrier.Transition.StateBefore = before;
    barrier.Transition.StateAfter = after;
    return barrier;
}

} // namespace

Swapchain::Swapchain(ContextHandle context, Queue& queue, const rhi::SwapchainDesc& desc)
    : context_(std::move(context)), queue_(queue), vsync_(desc.vsync) {
    if (desc.window.platform != rhi::NativeWindow::Platform::Win32 || desc.window.window == 0) {
        throw rhi::Error("D3D12 swapchain: presents to Win32 windows (HWND) only");
    }
    const HWND hwnd = reinterpret_cast<HWND>(desc.window.window);
    ComPtr<IDXGIFactory4> factory;
    check(CreateDXGIFactory2(0, IID_PPV_ARGS(&factory)), "CreateDXGIFactory2");
    tearingSupported_ = tearingSupported(factory.Get());

    const uint32_t framesInFlight = std::clamp(desc.framesInFlight, 2u, 3u);
    DXGI_SWAP_CHAIN_DESC1 info{};
    // 0 x 0 takes the window's client size; a minimised window gets its real size on resize().
    info.Width = desc.width;
    info.Height = desc.height;
    info.Format = kBufferFormat;
    info.SampleDesc.Count = 1;
    info.BufferUsage = DXGI_USAGE_BACK_BUFFER;
    // One buffer more than the frames in flight, as on Vulkan.
    info.BufferCount = framesInFlight + 1;
    info.Scaling = DXGI_SCALING_NONE;
    info.SwapEffect = DXGI_SWAP_EFFECT_FLIP_DISCARD;
    info.AlphaMode = DXGI_ALPHA_MODE_IGNORE;
    info.Flags = tearingSupported_ ? DXGI_SWAP_CHAIN_FLAG_ALLOW_TEARING : 0;
    ComPtr<IDXGISwapChain1> swapchain1;
    check(factory->CreateSwapChainForHwnd(queue_.native(), hwnd, &info, nullptr, nullptr, &swapchain1),
          "IDXGIFactory4::CreateSwapChainForHwnd");
    check(swapchain1.As(&swapchain_), "IDXGISwapChain1::QueryInterface(IDXGISwapChain3)");
    // The viewer handles fullscreen itself; Alt+Enter would resize behind its back.
    factory->MakeWindowAssociation(hwnd, DXGI_MWA_NO_ALT_ENTER);

    ID3D12Device* device = context_->device();
    slots_.resize(framesInFlight);
    for (FrameSlot& slot : slots_) {
        check(device->CreateCommandAllocator(D3D12_COMMAND_LIST_TYPE_DIRECT, IID_PPV_ARGS(&slot.allocator)),
              "CreateCommandAllocator", *context_);
    }
    check(device->CreateCommandList(0, D3D12_COMMAND_LIST_TYPE_DIRECT, slots_[0].allocator.Get(), nullptr,
                                    IID_PPV_ARGS(&commands_)),
          "CreateCommandList", *context_);
    check(commands_->Close(), "ID3D12GraphicsCommandList::Close", *context_);
    setDebugName(commands_.Get(), "swapchain copy");
    check(device->CreateFence(0, D3D12_FENCE_FLAG_NONE, IID_PPV_ARGS(&fence_)), "CreateFence", *context_);

    if (desc.width != 0 && desc.height != 0) {
        getBuffers();
    }
}

Swapchain::~Swapchain() {
    try {
        waitForPresents();
    } catch (const rhi::Error&) {
        // Device lost: nothing left to wait for, and destructors must not throw.
    }
}

void Swapchain::getBuffers() {
    DXGI_SWAP_CHAIN_DESC1 info{};
    check(swapchain_->GetDesc1(&info), "IDXGISwapChain1::GetDesc1");
    width_ = info.Width;
    height_ = info.Height;
    buffers_.resize(info.BufferCount);
    for (UINT i = 0; i < info.BufferCount; ++i) {
        check(swapchain_->GetBuffer(i, IID_PPV_ARGS(&buffers_[i])), "IDXGISwapChain::GetBuffer");
        setDebugName(buffers_[i].Get(), "swapchain buffer " + std::to_string(i));
    }
}

void Swapchain::waitForPresents() {
    for (FrameSlot& slot : slots_) {
        waitForFence(*context_, fence_.Get(), slot.fenceValue, "swapchain present");
        slot.source.reset();
    }
}

void Swapchain::resize(uint32_t width, uint32_t height, bool vsync) {
    waitForPresents();
    vsync_ = vsync;
    if (width == 0 || height == 0) {
        width_ = height_ = 0; // keeps the buffers; presents are skipped until a real size comes
        return;
    }
    buffers_.clear(); // ResizeBuffers fails while any reference to a buffer is held
    check(swapchain_->ResizeBuffers(0, width, height, DXGI_FORMAT_UNKNOWN,
                                    tearingSupported_ ? DXGI_SWAP_CHAIN_FLAG_ALLOW_TEARING : 0),
          "IDXGISwapChain::ResizeBuffers", *context_);
    getBuffers();
}

void Swapchain::recordCopy(ID3D12Resource* source, ID3D12Resource* target) {
    const D3D12_RESOURCE_BARRIER toCopy =
        transition(target, D3D12_RESOURCE_STATE_PRESENT, D3D12_RESOURCE_STATE_COPY_DEST);
    commands_->ResourceBarrier(1, &toCopy);
    commands_->CopyResource(target, source);
    const D3D12_RESOURCE_BARRIER toPresent =
        transition(target, D3D12_RESOURCE_STATE_COPY_DEST, D3D12_RESOURCE_STATE_PRESENT);
    commands_->ResourceBarrier(1, &toPresent);
}

rhi::PresentResult Swapchain::present(rhi::ITexture& image) {
    if (width_ == 0 || height_ == 0 || buffers_.empty()) {
        return rhi::PresentResult::Skipped;
    }
    const rhi::TextureDesc& desc = image.desc();
    if (desc.format != rhi::Format::RGBA8_UNORM || desc.width != width_ || desc.height != height_) {
        throw rhi::Error("present: texture '" + image.debugName() + "' must be RGBA8_UNORM " +
                         std::to_string(width_) + "x" + std::to_string(height_) + ", the swapchain's size");
    }
    if (image.trackedState != rhi::ResourceState::CopySource) {
        throw rhi::Error("present: texture '" + image.debugName() +
                         "' must be transitioned to CopySource by the last command list submitted");
    }
    NativeResource& source = nativeResource(image);
    FrameSlot& slot = slots_[frame_ % slots_.size()];
    waitForFence(*context_, fence_.Get(), slot.fenceValue, "swapchain present");
    slot.source = source.shared_from_this();

    check(slot.allocator->Reset(), "ID3D12CommandAllocator::Reset", *context_);
    check(commands_->Reset(slot.allocator.Get(), nullptr), "ID3D12GraphicsCommandList::Reset", *context_);
    recordCopy(source.native(), buffers_[swapchain_->GetCurrentBackBufferIndex()].Get());
    check(commands_->Close(), "ID3D12GraphicsCommandList::Close", *context_);

    // The same D3D12 queue as every command list submitted before: the copy runs after the
    // frame that wrote `image`.
    ID3D12CommandList* lists[] = {commands_.Get()};
    queue_.native()->ExecuteCommandLists(1, lists);
    const UINT flags = !vsync_ && tearingSupported_ ? DXGI_PRESENT_ALLOW_TEARING : 0;
    const HRESULT presented = swapchain_->Present(vsync_ ? 1 : 0, flags);
    check(queue_.native()->Signal(fence_.Get(), ++lastFenceValue_), "ID3D12CommandQueue::Signal", *context_);
    slot.fenceValue = lastFenceValue_;
    ++frame_;
    if (presented == DXGI_STATUS_OCCLUDED) {
        return rhi::PresentResult::Skipped;
    }
    check(presented, "IDXGISwapChain::Present", *context_);
    return rhi::PresentResult::Presented;
}

} // namespace lumina::d3d12
