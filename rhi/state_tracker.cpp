#include "rhi/state_tracker.h"

#include <string>

#include "rhi/error.h"

namespace lumina::rhi {

bool StateTracker::isWriteState(ResourceState state) {
    return state == ResourceState::UnorderedAccess || state == ResourceState::CopyDest;
}

void StateTracker::require(IResource& resource, ResourceState state) {
    if (const auto it = usedByCommand_.find(&resource); it != usedByCommand_.end()) {
        if (it->second != state) {
            throw Error("resource '" + resource.debugName() + "' is used as both " +
                        std::string(resourceStateName(it->second)) + " and " +
                        std::string(resourceStateName(state)) + " by one command");
        }
        return;
    }
    usedByCommand_.emplace(&resource, state);
    if (resource.trackedState != state) {
        transition(resource, state);
    } else if (isWriteState(state) && writtenSinceBarrier_.contains(&resource)) {
        sameStateBarrier(resource);
    }
}

void StateTracker::commandRecorded() {
    for (const auto& [resource, state] : usedByCommand_) {
        if (isWriteState(state)) {
            writtenSinceBarrier_.insert(resource);
        }
    }
    usedByCommand_.clear();
}

std::vector<Barrier> StateTracker::takeBarriers() {
    std::vector<Barrier> out;
    out.swap(pending_);
    return out;
}

void StateTracker::transition(IResource& resource, ResourceState state) {
    pending_.push_back({&resource, resource.trackedState, state});
    resource.trackedState = state;
    writtenSinceBarrier_.erase(&resource);
}

void StateTracker::sameStateBarrier(IResource& resource) {
    pending_.push_back({&resource, resource.trackedState, resource.trackedState});
    writtenSinceBarrier_.erase(&resource);
}

void StateTracker::reset() {
    pending_.clear();
    usedByCommand_.clear();
    writtenSinceBarrier_.clear();
}

} // namespace lumina::rhi
