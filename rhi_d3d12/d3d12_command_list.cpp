#include "rhi_d3d12/d3d12_command_list.h"

#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_queue.h"

namespace lumina::d3d12 {

namespace {

// PIX reads BeginEvent data with metadata 0 as a UTF-16 string (WINPIX_EVENT_UNICODE_VERSION);
// no WinPixEventRuntime needed.
constexpr UINT kPixUnicodeMetadata = 0;

bool isReadOnly(D3D12_RESOURCE_STATES state) {
    const D3D12_RESOURCE_STATES kWrites = D3D12_RESOURCE_STATE_UNORDERED_ACCESS |
                                          D3D12_RESOURCE_STATE_RENDER_TARGET |
                                          D3D12_RESOURCE_STATE_DEPTH_WRITE | D3D12_RESOURCE_STATE_COPY_DEST;
    return (state & kWrites) == 0;
}

} // namespace

CommandList::CommandList(ContextHandle context, std::shared_ptr<CommandListShared> shared,
                         rhi::QueueType type, std::string name)
    : context_(std::move(context)), shared_(std::move(shared)), type_(type), listType_(toD3D12(type)),
      name_(std::move(name)), viewTables_(*shared_->views), samplerTables_(*shared_->samplers),
      upload_(context_, name_), timers_(context_, listType_, shared_->timestampFrequency[size_t(type)],
                                        shared_->copyQueueTimestamps, name_) {
    ID3D12Device* device = context_->device();
    check(device->CreateCommandAllocator(listType_, IID_PPV_ARGS(&allocator_)),
          "ID3D12Device::CreateCommandAllocator('" + name_ + "')", *context_);
    setDebugName(allocator_.Get(), name_ + " allocator");
    check(device->CreateCommandList(0, listType_, allocator_.Get(), nullptr, IID_PPV_ARGS(&list_)),
          "ID3D12Device::CreateCommandList('" + name_ + "')", *context_);
    setDebugName(list_.Get(), name_);
    check(list_->Close(), "ID3D12GraphicsCommandList::Close('" + name_ + "')", *context_);
}

CommandList::~CommandList() {
    try {
        waitForPreviousSubmission();
    } catch (const std::exception& error) {
        context_->message(rhi::MessageSeverity::Error,
                          "destroying command list '" + name_ + "': " + std::string(error.what()));
    }
}

bool CommandList::finished() {
    return !fence_ || fence_->GetCompletedValue() >= fenceValue_;
}

void CommandList::waitForPreviousSubmission() {
    if (fence_) {
        waitForFence(*context_, fence_.Get(), fenceValue_, ("command list '" + name_ + "'").c_str());
    }
}

void CommandList::requireOpen(const char* command) const {
    if (recording_ != Recording::Open) {
        throw rhi::Error(std::string(command) + " on command list '" + name_ + "' outside begin()/end()");
    }
}

void CommandList::requireQueue(const char* command, bool graphicsOnly) const {
    if (listType_ == D3D12_COMMAND_LIST_TYPE_COPY ||
        (graphicsOnly && listType_ != D3D12_COMMAND_LIST_TYPE_DIRECT)) {
        throw rhi::Error(std::string(command) + " on command list '" + name_ + "': not available on the " +
                         (listType_ == D3D12_COMMAND_LIST_TYPE_COPY ? "copy" : "compute") +
                         " queue in D3D12");
    }
}

void CommandList::begin() {
    if (recording_ == Recording::Open) {
        throw rhi::Error("begin() on command list '" + name_ + "' that is already recording");
    }
    waitForPreviousSubmission();
    if (recording_ == Recording::Submitted) {
        previousResults_ = timers_.read();
        hasPreviousResults_ = true;
    }
    fence_.Reset();
    fenceValue_ = 0;
    check(allocator_->Reset(), "ID3D12CommandAllocator::Reset('" + name_ + "')", *context_);
    check(list_->Reset(allocator_.Get(), nullptr), "ID3D12GraphicsCommandList::Reset('" + name_ + "')",
          *context_);
    keptResources_.clear();
    keptSet_.clear();
    keptObjects_.clear();
    viewTables_.reset();
    samplerTables_.reset();
    upload_.reset();
    timers_.reset();
    tracker_.reset();
    commandUses_.clear();
    computePipeline_.reset();
    graphicsPipeline_.reset();
    root_ = nullptr;
    stateUses_.clear();
    indexBuffer_.reset();
    openRegions_.clear();
    if (listType_ != D3D12_COMMAND_LIST_TYPE_COPY) {
        ID3D12DescriptorHeap* heaps[] = {shared_->views->heap(), shared_->samplers->heap()};
        list_->SetDescriptorHeaps(2, heaps);
    }
    recording_ = Recording::Open;
}

void CommandList::end() {
    requireOpen("end()");
    if (!openRegions_.empty()) {
        throw rhi::Error("end() on command list '" + name_ + "': " + std::to_string(openRegions_.size()) +
                         " marker(s) or timer(s) were never ended");
    }
    timers_.resolve(list_.Get());
    flushBarriers();
    // Return decaying resources to COMMON (see NativeResource::isBuffer).
    std::vector<D3D12_RESOURCE_BARRIER> barriers;
    for (const auto& resource : keptResources_) {
        if (!resource->fixedState && (resource->isBuffer || listType_ == D3D12_COMMAND_LIST_TYPE_COPY)) {
            transitionNative(*resource, D3D12_RESOURCE_STATE_COMMON, barriers);
        }
    }
    if (!barriers.empty()) {
        list_->ResourceBarrier(static_cast<UINT>(barriers.size()), barriers.data());
    }
    check(list_->Close(), "ID3D12GraphicsCommandList::Close('" + name_ + "')", *context_);
    recording_ = Recording::Closed;
}

ID3D12CommandList* CommandList::prepareSubmit() {
    if (recording_ == Recording::Submitted) {
        throw rhi::Error("command list '" + name_ + "' submitted twice; begin() it again to re-record");
    }
    if (recording_ != Recording::Closed) {
        throw rhi::Error("command list '" + name_ + "' submitted before end()");
    }
    return list_.Get();
}

void CommandList::submitted(const ComPtr<ID3D12Fence>& fence, uint64_t value) {
    fence_ = fence;
    fenceValue_ = value;
    recording_ = Recording::Submitted;
}

void CommandList::keepAlive(NativeResource& resource) {
    if (keptSet_.insert(&resource).second) {
        keptResources_.push_back(resource.shared_from_this());
    }
}

void CommandList::use(rhi::IResource& resource, rhi::ResourceState state) {
    NativeResource& native = nativeResource(resource);
    keepAlive(native);
    if (native.fixedState) {
        if (state == rhi::ResourceState::CopyDest || state == rhi::ResourceState::UnorderedAccess) {
            throw rhi::Error("buffer '" + resource.debugName() + "' in Upload memory cannot be used as " +
                             std::string(rhi::resourceStateName(state)) +
                             " on D3D12 (upload heaps are read-only for the GPU; write it through map())");
        }
        return;
    }
    if (automaticBarriers_) {
        tracker_.require(resource, state);
    }
    commandUses_.emplace_back(&native, state);
}

void CommandList::transitionNative(NativeResource& resource, D3D12_RESOURCE_STATES state,
                                   std::vector<D3D12_RESOURCE_BARRIER>& barriers) {
    if (resource.currentState == state) {
        return;
    }
    D3D12_RESOURCE_BARRIER barrier{};
    barrier.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
    barrier.Transition.pResource = resource.native();
    barrier.Transition.Subresource = D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES;
    barrier.Transition.StateBefore = resource.currentState;
    barrier.Transition.StateAfter = state;
    barriers.push_back(barrier);
    resource.currentState = state;
}

void CommandList::flushBarriers() {
    std::vector<D3D12_RESOURCE_BARRIER> barriers;
    for (const rhi::Barrier& barrier : tracker_.takeBarriers()) {
        NativeResource& native = nativeResource(*barrier.resource);
        keepAlive(native);
        if (native.fixedState) {
            continue;
        }
        if (barrier.isSameState()) {
            if (barrier.after == rhi::ResourceState::UnorderedAccess) {
                D3D12_RESOURCE_BARRIER uav{};
                uav.Type = D3D12_RESOURCE_BARRIER_TYPE_UAV;
                uav.UAV.pResource = native.native();
                barriers.push_back(uav);
            } else {
                // Copy after copy: legacy barriers have no same-state copy barrier (a UAV
                // barrier orders UAV accesses only). A round trip through COPY_SOURCE is a pair
                // of transitions, and a transition waits for the writes of its before-state.
                const D3D12_RESOURCE_STATES state = native.currentState;
                transitionNative(native, D3D12_RESOURCE_STATE_COPY_SOURCE, barriers);
                transitionNative(native, state, barriers);
            }
            continue;
        }
        transitionNative(native, toD3D12State(barrier.after, listType_), barriers);
    }
    // The rhi state can be right while the D3D12 one is not: a buffer decayed to COMMON at the
    // end of the last list, or a texture read on a compute list lacks the pixel-shader bit.
    for (const auto& [native, state] : commandUses_) {
        const D3D12_RESOURCE_STATES required = toD3D12State(state, listType_);
        const D3D12_RESOURCE_STATES current = native->currentState;
        const bool satisfied =
            required == D3D12_RESOURCE_STATE_COMMON || current == required ||
            (isReadOnly(required) && isReadOnly(current) && (current & required) == required);
        if (!satisfied) {
            transitionNative(*native, required, barriers);
        }
    }
    if (!barriers.empty()) {
        list_->ResourceBarrier(static_cast<UINT>(barriers.size()), barriers.data());
    }
}

void CommandList::commandRecorded() {
    tracker_.commandRecorded();
    commandUses_.clear();
}

void CommandList::transition(rhi::IResource& resource, rhi::ResourceState state) {
    requireOpen("transition()");
    keepAlive(nativeResource(resource));
    tracker_.transition(resource, state);
}

void CommandList::uavBarrier(rhi::IResource& resource) {
    requireOpen("uavBarrier()");
    keepAlive(nativeResource(resource));
    tracker_.sameStateBarrier(resource);
}

void CommandList::commitBarriers() {
    requireOpen("commitBarriers()");
    flushBarriers();
}

void CommandList::beginEvent(std::string_view name) {
    const std::wstring wide = toWide(name);
    list_->BeginEvent(kPixUnicodeMetadata, wide.c_str(),
                      static_cast<UINT>((wide.size() + 1) * sizeof(wchar_t)));
}

void CommandList::beginMarker(std::string_view name) {
    requireOpen("beginMarker()");
    beginEvent(name);
    openRegions_.push_back(false);
}

void CommandList::endMarker() {
    requireOpen("endMarker()");
    if (openRegions_.empty() || openRegions_.back()) {
        throw rhi::Error("endMarker() on command list '" + name_ + "' without a matching beginMarker()" +
                         (openRegions_.empty() ? "" : " (the innermost open region is a timer)"));
    }
    list_->EndEvent();
    openRegions_.pop_back();
}

void CommandList::beginTimer(std::string_view name) {
    requireOpen("beginTimer()");
    timers_.begin(list_.Get(), name);
    beginEvent(name);
    openRegions_.push_back(true);
}

void CommandList::endTimer() {
    requireOpen("endTimer()");
    if (openRegions_.empty() || !openRegions_.back()) {
        throw rhi::Error("endTimer() on command list '" + name_ + "' without a matching beginTimer()" +
                         (openRegions_.empty() ? "" : " (the innermost open region is a marker)"));
    }
    timers_.end(list_.Get());
    list_->EndEvent();
    openRegions_.pop_back();
}

std::vector<rhi::TimerResult> CommandList::timerResults() {
    if (recording_ == Recording::Submitted) {
        if (!finished()) {
            throw rhi::Error("timerResults() on command list '" + name_ +
                             "': its submission has not finished (wait for its fence value first)");
        }
        return timers_.read();
    }
    return hasPreviousResults_ ? previousResults_ : std::vector<rhi::TimerResult>{};
}

} // namespace lumina::d3d12
