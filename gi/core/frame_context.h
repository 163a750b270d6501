#pragma once
// The frame as GI passes see it: each pass is declared where it is recorded, with its
// kernel, what it reads and writes (by HLSL register), its constants and its dispatch size.
// Barriers follow from the declaration (the RHI tracks states); every pass is timed under
// its name; a pass that does not run records why.
//
//   frame.compute("deferred: direct light", "deferred/direct_light")
//       .constantBuffer(0, frameConstants)
//       .read(0, gbuffer.albedo).read(1, gbuffer.normal)
//       .write(0, directLight)
//       .dispatchThreads(width, height, {8, 8});
#include "gi/core/pipeline_cache.h"
#include "rhi/rhi.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::gi {

class FiniteCheck;

// Why a pass did not run: it had nothing to do (no light of its kind, a strategy that draws no
// rays), or its output from an earlier frame still holds because nothing it reads changed. Only
// the second saves time that `lumina bench --verify-skips` can measure by forcing it off.
enum class SkipKind : uint8_t { NothingToRun, Reuse };

struct SkippedPass {
    std::string pass;
    std::string reason;
    SkipKind kind = SkipKind::NothingToRun;
};

class FrameContext;

// Bindings by register, shared by compute and raster passes.
template <typename Self>
class PassBindings {
public:
    Self& constantBuffer(uint32_t reg, rhi::BufferHandle buffer, uint32_t space = 0) {
        return bind(rhi::BindingSetItem::constantBuffer(reg, std::move(buffer)), space);
    }
    // t register: a sampled texture (all mips and layers).
    Self& read(uint32_t reg, rhi::TextureHandle texture, uint32_t space = 0) {
        return bind(rhi::BindingSetItem::sampledTexture(reg, std::move(texture)), space);
    }
    // t register: StructuredBuffer, or ByteAddressBuffer for Raw buffers without a stride.
    Self& read(uint32_t reg, rhi::BufferHandle buffer, uint32_t space = 0) {
        const bool raw = isRaw(*buffer);
        return bind(raw ? rhi::BindingSetItem::rawBuffer(reg, std::move(buffer))
                        : rhi::BindingSetItem::structuredBuffer(reg, std::move(buffer)),
                    space);
    }
    // u register: one mip of a storage texture.
    Self& write(uint32_t reg, rhi::TextureHandle texture, uint32_t mip = 0, uint32_t space = 0) {
        return bind(rhi::BindingSetItem::storageTexture(reg, std::move(texture), mip), space);
    }
    // u register: RWStructuredBuffer, or RWByteAddressBuffer for Raw buffers without a stride.
    Self& write(uint32_t reg, rhi::BufferHandle buffer, uint32_t space = 0) {
        const bool raw = isRaw(*buffer);
        return bind(raw ? rhi::BindingSetItem::rwRawBuffer(reg, std::move(buffer))
                        : rhi::BindingSetItem::rwStructuredBuffer(reg, std::move(buffer)),
                    space);
    }
    Self& sampler(uint32_t reg, rhi::SamplerHandle sampler, uint32_t space = 0) {
        return bind(rhi::BindingSetItem::samplerState(reg, std::move(sampler)), space);
    }
    Self& bind(rhi::BindingSetItem item, uint32_t space = 0) {
        if (bindings_.size() <= space) {
            bindings_.resize(space + 1);
        }
        bindings_[space].push_back(std::move(item));
        return static_cast<Self&>(*this);
    }
    // Push constants (root constants on D3D12): at most 128 bytes.
    template <typename T>
    Self& constants(const T& value) {
        static_assert(sizeof(T) % 4 == 0 && sizeof(T) <= 128,
                      "push constants: multiple of 4 bytes, at most 128");
        pushConstants_.resize(sizeof(T));
        std::memcpy(pushConstants_.data(), &value, sizeof(T));
        return static_cast<Self&>(*this);
    }

protected:
    static bool isRaw(const rhi::IBuffer& buffer) {
        return hasFlag(buffer.desc().usage, rhi::BufferUsage::Raw) && buffer.desc().structStride == 0;
    }
    std::vector<rhi::BindingSet> bindingSets(const std::vector<rhi::BindingLayoutHandle>& layouts) const;
    // The bindings that write (u registers), for the finite check.
    std::vector<rhi::BindingSetItem> writeBindings() const;

    SpaceBindings bindings_;
    std::vector<uint8_t> pushConstants_;
};

class ComputePass : public PassBindings<ComputePass> {
public:
    ComputePass(FrameContext& frame, std::string_view name, std::string_view kernel)
        : frame_(frame), name_(name), kernel_(kernel) {}

    void dispatch(uint32_t groupsX, uint32_t groupsY = 1, uint32_t groupsZ = 1);
    // One thread per element: the group counts round up.
    void dispatchThreads(uint32_t x, uint32_t y, uint32_t z, std::array<uint32_t, 3> groupSize);
    void dispatchThreads(uint32_t x, uint32_t y, std::array<uint32_t, 2> groupSize) {
        dispatchThreads(x, y, 1, {groupSize[0], groupSize[1], 1});
    }
    void dispatchIndirect(rhi::IBuffer& args, uint64_t offset = 0);

private:
    void record(auto&& issue);

    FrameContext& frame_;
    std::string name_;
    std::string kernel_;
};

// One draw of a raster pass, with its own push constants (an instance or material index).
struct RasterDraw {
    rhi::DrawArgs args;
    std::array<uint8_t, 128> constants{};
    uint32_t constantBytes = 0;

    template <typename T>
    static RasterDraw with(const rhi::DrawArgs& args, const T& value) {
        static_assert(sizeof(T) % 4 == 0 && sizeof(T) <= 128,
                      "push constants: multiple of 4 bytes, at most 128");
        RasterDraw draw{args};
        std::memcpy(draw.constants.data(), &value, sizeof(T));
        draw.constantBytes = sizeof(T);
        return draw;
    }
};

// A raster pass: vertex + pixel kernels drawing into attachments (loaded, not cleared).
class RasterPass : public PassBindings<RasterPass> {
public:
    RasterPass(FrameContext& frame, std::string_view name, std::string_view vertexKernel,
               std::string_view pixelKernel)
        : frame_(frame), name_(name), vertexKernel_(vertexKernel), pixelKernel_(pixelKernel) {}

    RasterPass& state(const RasterPipelineState& state) {
        state_ = state;
        return *this;
    }
    RasterPass& colorTarget(rhi::TextureHandle texture, uint32_t arrayLayer = 0, uint32_t mip = 0) {
        colors_.push_back({std::move(texture), mip, arrayLayer});
        return *this;
    }
    RasterPass& depthTarget(rhi::TextureHandle texture, uint32_t arrayLayer = 0) {
        depth_ = rhi::Attachment{std::move(texture), 0, arrayLayer};
        return *this;
    }
    RasterPass& viewport(const rhi::Viewport& viewport) {
        viewport_ = viewport;
        return *this;
    }
    RasterPass& indexBuffer(rhi::BufferHandle buffer, rhi::IndexFormat format = rhi::IndexFormat::Uint32) {
        index_ = rhi::IndexBufferBinding{std::move(buffer), format, 0};
        return *this;
    }
    // Records every draw under the pass's timer. Draws carry their own push constants; all
    // of them must have the same size (the pipeline's push-constant range).
    void draw(const std::vector<RasterDraw>& draws, bool indexed);

private:
    FrameContext& frame_;
    std::string name_;
    std::string vertexKernel_;
    std::string pixelKernel_;
    RasterPipelineState state_;
    std::vector<rhi::Attachment> colors_;
    std::optional<rhi::Attachment> depth_;
    rhi::Viewport viewport_;
    std::optional<rhi::IndexBufferBinding> index_;
};

class FrameContext {
public:
    FrameContext(PipelineCache& pipelines, rhi::ICommandList& commands, uint64_t frameIndex)
        : pipelines_(pipelines), commands_(commands), frameIndex_(frameIndex) {}

    ComputePass compute(std::string_view passName, std::string_view kernel) {
        return ComputePass(*this, passName, kernel);
    }
    RasterPass raster(std::string_view passName, std::string_view vertexKernel,
                      std::string_view pixelKernel) {
        return RasterPass(*this, passName, vertexKernel, pixelKernel);
    }
    // A pass that does not run this frame because it has nothing to do, and why ("no point lights").
    void skip(std::string_view passName, std::string_view reason) {
        skipped_.push_back({std::string(passName), std::string(reason), SkipKind::NothingToRun});
    }
    // A pass that does not run because its earlier output still holds. A pass forced to run that
    // still skips had nothing at all to do (no cards, no probes), and is recorded as such.
    void skipReused(std::string_view passName, std::string_view reason) {
        const SkipKind kind = mayReuse(passName) ? SkipKind::Reuse : SkipKind::NothingToRun;
        skipped_.push_back({std::string(passName), std::string(reason), kind});
    }
    // Whether `passName` may skip work whose output would not change (a shadow map of geometry
    // that did not move, radiosity that converged). False for a pass forced to run: `lumina bench
    // --verify-skips` measures what each skip saves and that the image does not change without it
    // (docs/measurement.md#skips).
    bool mayReuse(std::string_view passName) const {
        return !forced_ || std::find(forced_->begin(), forced_->end(), passName) == forced_->end();
    }
    // The passes whose reuse skips are forced off from now on (mayReuse); null: none. Not owned.
    void setForcedPasses(const std::vector<std::string>* passes) { forced_ = passes; }

    rhi::ICommandList& commands() { return commands_; }
    PipelineCache& pipelines() { return pipelines_; }
    rhi::IDevice& device() { return pipelines_.device(); }
    uint64_t frameIndex() const { return frameIndex_; }
    const std::vector<SkippedPass>& skipped() const { return skipped_; }

    // --check-finite (gi/core/finite_check.h): every pass recorded from now on is followed by a
    // check of the float resources it wrote. Null: none (the default).
    void setFiniteCheck(FiniteCheck* check) { finiteCheck_ = check; }
    FiniteCheck* finiteCheck() const { return finiteCheck_; }

private:
    PipelineCache& pipelines_;
    rhi::ICommandList& commands_;
    uint64_t frameIndex_;
    std::vector<SkippedPass> skipped_;
    FiniteCheck* finiteCheck_ = nullptr;
    const std::vector<std::string>* forced_ = nullptr;
};

} // namespace lumina::gi
