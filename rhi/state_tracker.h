#pragma once
// Resource-state tracking, written once for both backends. A command list asks for the
// state each resource must be in for its next command; the tracker answers with the
// barriers to record first. A resource written through a UAV (or a copy) and used the
// same way again gets a same-state barrier (a UAV barrier on D3D12, a memory barrier on
// Vulkan), so dispatch chains that read what the previous dispatch wrote stay ordered.
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "rhi/resource.h"

namespace lumina::rhi {

struct Barrier {
    IResource* resource = nullptr;
    ResourceState before = ResourceState::Undefined;
    ResourceState after = ResourceState::Undefined;
    // before == after: a same-state barrier ordering two writes, or a write and a read
    bool isSameState() const { return before == after; }
};

class StateTracker {
public:
    // The next command uses `resource` in `state`. Throws rhi::Error when one command asks
    // for two different states of one resource (say, bound as both SRV and UAV).
    void require(IResource& resource, ResourceState state);
    // Records that the command just issued wrote through its UAV and copy-destination uses.
    void commandRecorded();
    // Barriers to record before the next command, in request order; clears the queue.
    std::vector<Barrier> takeBarriers();
    bool hasPendingBarriers() const { return !pending_.empty(); }
    // Explicit control: forces a transition, or a same-state barrier.
    void transition(IResource& resource, ResourceState state);
    void sameStateBarrier(IResource& resource);
    void reset();

private:
    static bool isWriteState(ResourceState state);

    std::vector<Barrier> pending_;
    std::unordered_map<IResource*, ResourceState> usedByCommand_;
    std::unordered_set<IResource*> writtenSinceBarrier_;
};

} // namespace lumina::rhi
