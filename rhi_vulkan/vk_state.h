#pragma once
// rhi::ResourceState to what Vulkan's synchronization2 barriers need: the image layout,
// the accesses and the pipeline stages of each state.
#include "rhi/resource_state.h"
#include "rhi/state_tracker.h"

#include <vector>
#include <vulkan/vulkan.h>

namespace lumina::vulkan {

struct StateAccess {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
};

// `graphicsQueue`: false on a compute-only queue, whose barriers may not name vertex,
// fragment or attachment stages; those become ALL_COMMANDS there.
StateAccess stateAccess(rhi::ResourceState state, bool graphicsQueue);

// Only the write accesses of a state: the source scope of a same-state barrier.
VkAccessFlags2 writeAccess(VkAccessFlags2 access);

// Records `barriers` (from rhi::StateTracker) with one vkCmdPipelineBarrier2. Transitions
// become buffer or image barriers; same-state barriers (UAV -> UAV, CopyDest -> CopyDest)
// become global memory barriers, which order the writes without a layout change.
void recordBarriers(VkCommandBuffer commandBuffer, const std::vector<rhi::Barrier>& barriers,
                    bool graphicsQueue);

} // namespace lumina::vulkan
