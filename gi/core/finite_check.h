#pragma once
// `lumina render --check-finite` (docs/gi_tests.md, "Poison"): after every pass a frame records,
// a small kernel (shaders/debug/finite_check.hlsl) counts the NaN and +-Inf values in each float
// resource the pass wrote: the storage textures (the mip it wrote), the colour targets of a
// raster pass, and the buffers of float4 registered with watchBuffer. After the frame, report()
// names the first pass, in recording order, that wrote a non-finite value, and where.
//
//   FiniteCheck check(device);
//   FrameContext frame(pipelines, list, index);
//   check.beginFrame(frame);          // clears the counters; the frame's passes report to it
//   renderer.render(frame);
//   ... submit, wait ...
//   if (auto bad = check.report()) throw std::runtime_error(bad->describe());
//
// A debug mode: every check is a dispatch and a barrier, and report() waits for the GPU.
// Unsigned-integer, unorm and depth resources are not checked (they cannot hold NaN or Inf),
// nor textures without sampled usage or cube textures (none of the GI's float outputs is one).
#include "rhi/rhi.h"

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::gi {

class FrameContext;

// The first non-finite value a frame's finite check found.
struct NonFiniteWrite {
    uint64_t frame = 0;
    std::string pass;     // the pass's name, as --timings prints it
    std::string resource; // the texture's or buffer's debug name, with its mip
    uint64_t count = 0;   // non-finite components in that resource after the pass
    std::string describe() const;
};

class FiniteCheck {
public:
    // At most `maxChecksPerFrame` resources are checked a frame (a frame that records more is
    // an error: report() would miss the rest).
    explicit FiniteCheck(rhi::IDevice& device, uint32_t maxChecksPerFrame = 8192);

    // Checks `buffer` (a structured buffer of float4: stride 16, floats only) after every pass
    // that writes it. Buffers are not checked otherwise: most mix floats with integers.
    void watchBuffer(const rhi::IBuffer& buffer);

    // Clears the counters and attaches the check to `frame`: every pass recorded into it from
    // now on is checked.
    void beginFrame(FrameContext& frame);
    // Called by the frame after it recorded pass `pass` (which wrote `writes` and `colorTargets`).
    void afterPass(FrameContext& frame, std::string_view pass, const std::vector<rhi::BindingSetItem>& writes,
                   const std::vector<rhi::Attachment>& colorTargets);
    // After the frame's submission finished: the first non-finite write, if any. Reads the
    // counters back (waits for the GPU).
    std::optional<NonFiniteWrite> report();

    // Resources checked in the last frame begun.
    uint32_t checksLastFrame() const { return uint32_t(checks_.size()); }

private:
    struct Check {
        std::string pass;
        std::string resource;
    };
    void checkTexture(FrameContext& frame, std::string_view pass, const rhi::TextureHandle& texture,
                      uint32_t mip);
    void checkBuffer(FrameContext& frame, std::string_view pass, const rhi::BufferHandle& buffer);
    void dispatch(FrameContext& frame, std::string_view kernel, rhi::BindingSetItem resource,
                  std::array<uint32_t, 4> extent, std::array<uint32_t, 3> groupSize);

    rhi::IDevice& device_;
    uint32_t maxChecks_;
    rhi::BufferHandle counts_;
    std::set<const rhi::IBuffer*> watched_;
    std::vector<Check> checks_; // this frame's, in recording order: check i counts into slot i
    uint64_t frameIndex_ = 0;
};

} // namespace lumina::gi
