#include "tests/pathtracer/path_tracer_fixture.h"

#include "gi/core/frame_context.h"
#include "gi/scene/scene_loader.h"

#include <algorithm>
#include <cmath>

namespace lumina::test {

void PathTracerTest::SetUp() {
    GpuTest::SetUp();
#ifdef LUMINA_REQUIRE_KERNELS
    LUMINA_REQUIRE_KERNELS(); // a backend without kernels in its format skips
#endif
}

void PathTracerTest::TearDown() {
    pipelines_.reset();
    GpuTest::TearDown();
}

gi::PipelineCache& PathTracerTest::pipelines() {
    if (!pipelines_) {
        pipelines_ = std::make_unique<gi::PipelineCache>(device(), shaders());
    }
    return *pipelines_;
}

void PathTracerTest::addSamples(gi::PathTracer& tracer, uint32_t count) {
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    gi::FrameContext frame(pipelines(), *list, tracer.samples());
    tracer.recordSamples(frame, count);
    list->end();
    submitAndWait(*list);
}

gi::PathTracerResult PathTracerTest::render(const scene::Scene& scene, const gi::PathTracerSettings& settings,
                                            uint32_t spp, uint32_t perSubmission) {
    const gi::PathTracerScene traced(device(), scene);
    gi::PathTracer tracer(device(), traced, scene, settings);
    while (tracer.samples() < spp) {
        addSamples(tracer, std::min(perSubmission, spp - tracer.samples()));
    }
    return tracer.readResult();
}

scene::Scene loadBuiltin(const char* name, uint32_t width, uint32_t height) {
    scene::Scene loaded = scene::loadScene(name);
    loaded.image = {width, height};
    return loaded;
}

ChannelMean channelMean(const image::Image& image, const char* channel, const char* varianceChannel) {
    const std::span<const float> values = image.channel(channel);
    const std::span<const float> variances = image.channel(varianceChannel);
    double sum = 0.0, varianceSum = 0.0;
    for (size_t i = 0; i < values.size(); ++i) {
        sum += values[i];
        varianceSum += variances[i];
    }
    const double n = double(values.size());
    return {sum / n, std::sqrt(varianceSum) / n};
}

} // namespace lumina::test
