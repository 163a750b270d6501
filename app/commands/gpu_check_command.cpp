// `lumina gpu-check`: runs one kernel on the chosen device and checks every value it wrote.
#include "app/command.h"
#include "rhi/rhi.h"
#include "shaders/common/constants_shared.h"

#include <chrono>
#include <iostream>
#include <vector>

namespace lumina::app {

namespace {

struct GpuCheckConstants {
    uint32_t count;
    uint32_t seed;
    uint32_t pad[2];
};

// Same hash as shaders/app/gpu_check.hlsl.
uint32_t pcgHash(uint32_t value) {
    const uint32_t state = value * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

int runGpuCheck(const ParsedArgs& args) {
    const auto count = static_cast<uint32_t>(args.getUint("count", 1u << 20, 1, 1u << 26));
    const auto seed = static_cast<uint32_t>(args.common.seed);

    rhi::DeviceHandle device = openDevice(args.common);
    std::cout << "device: " << device->adapter().name << " (" << rhi::apiName(device->api()) << ", driver "
              << device->adapter().driver << ")\n";

    rhi::ShaderLibrary shaders(*device);
    auto layout = device->createBindingLayout({.items = {{rhi::BindingType::BufferUAV, 0}}});
    auto pipeline = device->createComputePipeline({.shader = shaders.get("app/gpu_check"),
                                                   .layouts = {layout},
                                                   .pushConstantBytes = sizeof(GpuCheckConstants),
                                                   .debugName = "gpu check"});
    auto output = device->createBuffer({.size = uint64_t(count) * sizeof(uint32_t),
                                        .structStride = sizeof(uint32_t),
                                        .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                        .debugName = "gpu check output"});

    auto list = device->createCommandList();
    list->begin();
    list->beginTimer("gpu check");
    list->setComputeState({pipeline, {{layout, {rhi::BindingSetItem::rwStructuredBuffer(0, output)}}}});
    list->pushConstants(GpuCheckConstants{count, seed, {0, 0}});
    list->dispatch((count + LUMINA_LINEAR_GROUP_SIZE - 1) / LUMINA_LINEAR_GROUP_SIZE);
    list->endTimer();
    list->end();
    auto& queue = device->queue(rhi::QueueType::Graphics);
    queue.waitForValue(queue.submit(*list));

    const auto values = rhi::readBufferAs<uint32_t>(*device, *output);
    uint32_t wrong = 0;
    for (uint32_t i = 0; i < count; ++i) {
        if (values[i] != pcgHash(i ^ seed)) {
            if (wrong++ < 5) {
                std::cerr << "gpu-check: element " << i << " is " << values[i] << ", expected "
                          << pcgHash(i ^ seed) << '\n';
            }
        }
    }
    const auto timers = list->timerResults();
    std::cout << "kernel: " << count << " values in " << (timers.empty() ? 0.0 : timers.front().milliseconds)
              << " ms of GPU time, " << wrong << " wrong\n";
    if (device->validationMessageCount() != 0) {
        std::cerr << "gpu-check: " << device->validationMessageCount() << " validation message(s)\n";
        return 1;
    }
    std::cout << (wrong == 0 ? "gpu-check: OK\n" : "gpu-check: FAILED\n");
    return wrong == 0 ? 0 : 1;
}

} // namespace

Command gpuCheckCommand() {
    return {.name = "gpu-check",
            .summary = "run one kernel on the GPU and verify its output",
            .usage = "lumina gpu-check [--count N] [--api vulkan|d3d12] [--device N] [--validation]",
            .description =
                "Compiles nothing at run time: loads the prebuilt kernel app/gpu_check, dispatches it over "
                "N elements, reads the result back and checks every value against the CPU. Exit code 0 "
                "when all match and the validation layer (with --validation) stayed silent.",
            .flags = {{"count", "N", "number of elements (default 1048576)"}},
            .run = runGpuCheck};
}

} // namespace lumina::app
