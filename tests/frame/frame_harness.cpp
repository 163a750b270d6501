#include "tests/frame/frame_harness.h"

#include <algorithm>

namespace lumina::test {

namespace {

gi::FrameRendererSettings rendererSettings(const scene::Scene& scene, const FrameHarnessSettings& settings) {
    gi::FrameRendererSettings out;
    out.technique = settings.technique;
    // The preset's shadow maps, as lumina render and lumina bench use them (one table, preset.h).
    const gi::Preset& preset = gi::findPreset(settings.preset);
    out.deferred = {.width = settings.width,
                    .height = settings.height,
                    .sunShadowSize = preset.sunShadowSize,
                    .pointShadowSize = preset.pointShadowSize,
                    .log = [](std::string_view) {}};
    if (settings.technique == gi::GiTechnique::Lumen) {
        out.lumen = testLumenSettings(settings.preset, scene);
        if (settings.probeSpacing != 0) {
            out.lumen->probes.probeSpacing = settings.probeSpacing;
        }
        if (settings.adjustLumen) {
            settings.adjustLumen(*out.lumen);
        }
    }
    if (settings.technique == gi::GiTechnique::Ddgi) {
        out.ddgi = testDdgiSettings(settings.preset, scene);
        if (settings.adjustDdgi) {
            settings.adjustDdgi(*out.ddgi);
        }
    }
    if (settings.technique == gi::GiTechnique::ShGrid) {
        out.shGrid = gi::shGridPreset(preset, scene);
        if (settings.adjustShGrid) {
            settings.adjustShGrid(*out.shGrid);
        }
    }
    return out;
}

// Path-tracer samples per submission: short dispatches on lavapipe.
constexpr uint32_t kSamplesPerSubmission = 32;

} // namespace

gi::LumenSettings testLumenSettings(const std::string& name, const scene::Scene& scene) {
    gi::LumenSettings settings = gi::lumenPreset(name, scene);
    settings.sdf.useCache = false;
    return settings;
}

gi::DdgiSettings testDdgiSettings(const std::string& name, const scene::Scene& scene) {
    gi::DdgiSettings settings = gi::ddgiPreset(name, scene);
    settings.sdf.useCache = false;
    return settings;
}

FrameHarness::FrameHarness(rhi::IDevice& device, rhi::ShaderLibrary& shaders, scene::Scene scene,
                           const FrameHarnessSettings& settings)
    : device_(device), scene_(std::move(scene)), gpuScene_(device, scene_), pipelines_(device, shaders),
      renderer_(device, scene_, gpuScene_, rendererSettings(scene_, settings)),
      list_(device.createCommandList()),
      finiteCheck_(settings.checkFinite ? std::make_unique<gi::FiniteCheck>(device) : nullptr) {}

void FrameHarness::render(uint32_t count) {
    for (uint32_t i = 0; i < count; ++i) {
        list_->begin();
        gi::FrameContext frame(pipelines_, *list_, frames_++);
        if (finiteCheck_) {
            finiteCheck_->beginFrame(frame);
        }
        renderer_.render(frame);
        list_->end();
        rhi::IQueue& queue = device_.queue(list_->queueType());
        queue.waitForValue(queue.submit(*list_));
        timings_.addFrame(list_->timerResults(), frame.skipped());
        if (finiteCheck_) {
            nonFinite_ = finiteCheck_->report();
        }
    }
}

uint32_t FrameHarness::renderWithAsyncCompute(uint32_t count) {
    if (!asyncList_) {
        asyncList_ = device_.createCommandList(rhi::QueueType::Compute);
        gatherList_ = device_.createCommandList(rhi::QueueType::Graphics);
    }
    rhi::IQueue& graphics = device_.queue(rhi::QueueType::Graphics);
    rhi::IQueue& compute = device_.queue(rhi::QueueType::Compute);
    uint32_t asyncFrames = 0;
    for (uint32_t i = 0; i < count; ++i) {
        list_->begin();
        asyncList_->begin();
        gatherList_->begin();
        gi::FrameContext raster(pipelines_, *list_, frames_);
        gi::FrameContext async(pipelines_, *asyncList_, frames_);
        gi::FrameContext gather(pipelines_, *gatherList_, frames_);
        ++frames_;
        const bool besideRaster = renderer_.render(gi::SplitFrame{raster, async, gather});
        list_->end();
        asyncList_->end();
        gatherList_->end();
        std::vector<rhi::TimerResult> timers;
        std::vector<gi::SkippedPass> skipped = raster.skipped();
        uint64_t asyncDone = 0;
        if (besideRaster) {
            asyncDone = compute.submit(*asyncList_);
            ++asyncFrames;
        }
        graphics.submit(*list_);
        if (besideRaster) {
            graphics.waitForQueue(compute, asyncDone);
        }
        graphics.waitForValue(graphics.submit(*gatherList_));
        if (besideRaster) {
            // The gather waited for it on the GPU; its timers are read once the CPU has seen it end.
            compute.waitForValue(asyncDone);
        }
        for (rhi::ICommandList* list :
             {list_.get(), besideRaster ? asyncList_.get() : nullptr, gatherList_.get()}) {
            if (list != nullptr) {
                const std::vector<rhi::TimerResult> results = list->timerResults();
                timers.insert(timers.end(), results.begin(), results.end());
            }
        }
        for (const gi::FrameContext* part : {&async, &gather}) {
            skipped.insert(skipped.end(), part->skipped().begin(), part->skipped().end());
        }
        timings_.addFrame(timers, skipped);
    }
    return asyncFrames;
}

bool FrameHarness::converged() const {
    return renderer_.gi() == nullptr || renderer_.gi()->converged();
}

uint32_t FrameHarness::renderUntilConverged(uint32_t extraFrames, uint32_t maxFrames) {
    const uint32_t start = frames_;
    while (!converged() && frames_ - start < maxFrames) {
        render();
    }
    render(std::min(extraFrames, maxFrames - (frames_ - start)));
    return frames_ - start;
}

image::Image FrameHarness::hdr() {
    return rgbOnly(read(renderer_.deferred().hdr()));
}

image::Image FrameHarness::direct() {
    return rgbOnly(read(renderer_.deferred().direct()));
}

image::Image FrameHarness::indirect() {
    image::Image out = hdr();
    const image::Image lit = direct();
    for (const char* c : {"R", "G", "B"}) {
        const std::span<float> values = out.channel(c);
        const std::span<const float> subtract = lit.channel(c);
        for (size_t i = 0; i < values.size(); ++i) {
            values[i] -= subtract[i];
        }
    }
    return out;
}

image::Image rgbOnly(const image::Image& image) {
    image::Image out = image::Image::rgb(image.width(), image.height());
    for (const char* c : {"R", "G", "B"}) {
        std::ranges::copy(image.channel(c), out.channel(c).begin());
    }
    return out;
}

image::Image rgbOf(const image::Image& image, const std::string& prefix) {
    image::Image out = image::Image::rgb(image.width(), image.height());
    for (const char* c : {"R", "G", "B"}) {
        std::ranges::copy(image.channel(prefix + "." + c), out.channel(c).begin());
    }
    return out;
}

gi::PathTracerResult pathTracedReference(rhi::IDevice& device, gi::PipelineCache& pipelines,
                                         const scene::Scene& scene, uint32_t width, uint32_t height,
                                         uint32_t spp) {
    gi::PathTracerScene traced(device, scene);
    gi::PathTracer tracer(device, traced, scene,
                          {.width = width, .height = height, .jitter = false, .aovs = true});
    rhi::CommandListHandle list = device.createCommandList();
    for (uint32_t done = 0; done < spp; done += kSamplesPerSubmission) {
        list->begin();
        gi::FrameContext frame(pipelines, *list, done);
        tracer.recordSamples(frame, std::min(kSamplesPerSubmission, spp - done));
        list->end();
        rhi::IQueue& queue = device.queue(list->queueType());
        queue.waitForValue(queue.submit(*list));
    }
    return tracer.readResult();
}

} // namespace lumina::test
