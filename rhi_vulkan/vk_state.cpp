#include "rhi_vulkan/vk_state.h"

#include "rhi/error.h"
#include "rhi_vulkan/vk_buffer.h"
#include "rhi_vulkan/vk_format.h"
#include "rhi_vulkan/vk_struct.h"
#include "rhi_vulkan/vk_texture.h"

namespace lumina::vulkan {

namespace {

constexpr VkPipelineStageFlags2 kGraphicsShaders =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags2 kDepthTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
// Stages that only a graphics-capable queue may name in a barrier.
constexpr VkPipelineStageFlags2 kGraphicsOnlyStages = kGraphicsShaders | kDepthTests |
                                                      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                      VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT;

StateAccess baseAccess(rhi::ResourceState state) {
    using S = rhi::ResourceState;
    switch (state) {
    case S::Undefined:
        return {VK_IMAGE_LAYOUT_UNDEFINED, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_NONE};
    case S::Common:
        // Freshly created or host-visible resources: anything may have touched them.
        return {VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
                VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
    case S::ConstantBuffer:
        return {VK_IMAGE_LAYOUT_UNDEFINED, VK_ACCESS_2_UNIFORM_READ_BIT,
                kGraphicsShaders | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT};
    case S::IndexBuffer:
        return {VK_IMAGE_LAYOUT_UNDEFINED, VK_ACCESS_2_INDEX_READ_BIT, VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT};
    case S::IndirectArgument:
        return {VK_IMAGE_LAYOUT_UNDEFINED, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT};
    case S::ShaderResource:
        return {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_2_SHADER_READ_BIT,
                kGraphicsShaders | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT};
    case S::UnorderedAccess:
        return {VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT,
                kGraphicsShaders | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT};
    case S::RenderTarget:
        return {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
    case S::DepthWrite:
        return {VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                kDepthTests};
    case S::DepthRead:
        // Read-only depth attachment that shaders may sample at the same time.
        return {VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_SHADER_READ_BIT,
                kDepthTests | kGraphicsShaders | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT};
    case S::CopySource:
        return {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_2_TRANSFER_READ_BIT,
                VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT};
    case S::CopyDest:
        return {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT};
    case S::Present:
        // The RHI has no swapchain yet (VK_KHR_swapchain is not enabled), so PRESENT_SRC_KHR
        // is not a legal layout: presentable images wait in GENERAL.
        return {VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_2_MEMORY_READ_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
    }
    throw rhi::Error("stateAccess: invalid resource state " + std::to_string(static_cast<int>(state)));
}

VkBufferMemoryBarrier2 bufferBarrier(const Buffer& buffer, const StateAccess& before,
                                     const StateAccess& after) {
    auto barrier = vkStruct<VkBufferMemoryBarrier2>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2);
    barrier.srcStageMask = before.stages;
    barrier.srcAccessMask = writeAccess(before.access);
    barrier.dstStageMask = after.stages;
    barrier.dstAccessMask = after.access;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.buffer = buffer.handle();
    barrier.offset = 0;
    barrier.size = VK_WHOLE_SIZE;
    return barrier;
}

VkImageMemoryBarrier2 imageBarrier(const Texture& texture, const StateAccess& before,
                                   const StateAccess& after) {
    auto barrier = vkStruct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
    barrier.srcStageMask = before.stages;
    // A layout transition is itself a write: it must wait for earlier reads as well, which
    // the execution dependency on srcStageMask provides; only writes need making available.
    barrier.srcAccessMask = writeAccess(before.access);
    barrier.dstStageMask = after.stages;
    barrier.dstAccessMask = after.access;
    barrier.oldLayout = before.layout;
    barrier.newLayout = after.layout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = texture.handle();
    barrier.subresourceRange = texture.fullRange();
    return barrier;
}

} // namespace

StateAccess stateAccess(rhi::ResourceState state, bool graphicsQueue) {
    StateAccess result = baseAccess(state);
    if (!graphicsQueue && (result.stages & kGraphicsOnlyStages)) {
        result.stages &= ~kGraphicsOnlyStages;
        if (result.stages == VK_PIPELINE_STAGE_2_NONE) {
            result.stages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        }
    }
    return result;
}

VkAccessFlags2 writeAccess(VkAccessFlags2 access) {
    constexpr VkAccessFlags2 kWrites =
        VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
        VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    return access & kWrites;
}

void recordBarriers(VkCommandBuffer commandBuffer, const std::vector<rhi::Barrier>& barriers,
                    bool graphicsQueue) {
    if (barriers.empty()) {
        return;
    }
    std::vector<VkMemoryBarrier2> memoryBarriers;
    std::vector<VkBufferMemoryBarrier2> bufferBarriers;
    std::vector<VkImageMemoryBarrier2> imageBarriers;
    for (const rhi::Barrier& barrier : barriers) {
        const StateAccess before = stateAccess(barrier.before, graphicsQueue);
        const StateAccess after = stateAccess(barrier.after, graphicsQueue);
        if (barrier.isSameState()) {
            auto memory = vkStruct<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
            memory.srcStageMask = before.stages;
            memory.srcAccessMask = writeAccess(before.access);
            memory.dstStageMask = after.stages;
            memory.dstAccessMask = after.access;
            memoryBarriers.push_back(memory);
        } else if (const auto* buffer = dynamic_cast<const Buffer*>(barrier.resource)) {
            bufferBarriers.push_back(bufferBarrier(*buffer, before, after));
        } else if (const auto* texture = dynamic_cast<const Texture*>(barrier.resource)) {
            imageBarriers.push_back(imageBarrier(*texture, before, after));
        } else {
            throw rhi::Error("barrier on '" + barrier.resource->debugName() +
                             "', which is not a Vulkan buffer or texture of this backend");
        }
    }
    auto dependency = vkStruct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dependency.memoryBarrierCount = static_cast<uint32_t>(memoryBarriers.size());
    dependency.pMemoryBarriers = memoryBarriers.data();
    dependency.bufferMemoryBarrierCount = static_cast<uint32_t>(bufferBarriers.size());
    dependency.pBufferMemoryBarriers = bufferBarriers.data();
    dependency.imageMemoryBarrierCount = static_cast<uint32_t>(imageBarriers.size());
    dependency.pImageMemoryBarriers = imageBarriers.data();
    vkCmdPipelineBarrier2(commandBuffer, &dependency);
}

} // namespace lumina::vulkan
