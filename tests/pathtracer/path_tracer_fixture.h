#pragma once
// GPU tests of the reference path tracer: a device with validation on (GpuTest), a pipeline
// cache, and renders of small images in a few submissions.
#include "gi/core/pipeline_cache.h"
#include "gi/pathtracer/path_tracer.h"
#include "gi/pathtracer/path_tracer_scene.h"
#include "gi/scene/scene.h"
#include "tests/rhi/gpu_test_fixture.h"

#include <cstdint>
#include <functional>
#include <memory>

namespace lumina::test {

class PathTracerTest : public GpuTest {
public:
    gi::PipelineCache& pipelines();
    // Records `count` samples in one submission and waits for it.
    void addSamples(gi::PathTracer& tracer, uint32_t count);
    // A whole render: `spp` samples in submissions of at most `perSubmission`.
    gi::PathTracerResult render(const scene::Scene& scene, const gi::PathTracerSettings& settings,
                                uint32_t spp, uint32_t perSubmission = 32);

protected:
    void SetUp() override;
    void TearDown() override;

private:
    std::unique_ptr<gi::PipelineCache> pipelines_;
};

// A loaded built-in scene with its image size replaced.
scene::Scene loadBuiltin(const char* name, uint32_t width, uint32_t height);

// Mean of one channel over the image, and the standard error of that mean from the
// variance channel (pixels are independent): sqrt(sum variance) / pixels.
struct ChannelMean {
    double mean = 0.0;
    double standardError = 0.0;
};
ChannelMean channelMean(const image::Image& image, const char* channel, const char* varianceChannel);

} // namespace lumina::test
