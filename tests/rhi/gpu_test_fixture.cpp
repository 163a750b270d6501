#include "tests/rhi/gpu_test_fixture.h"

#include <filesystem>
#include <iostream>
#include <sstream>

namespace lumina::test {

void GpuTestFixture::openDevice(rhi::Api api, bool validation) {
    rhi::DeviceDesc desc;
    desc.validation = validation;
    desc.synchronizationValidation = validation;
    if (!validation) {
        std::cout << "[ info ] validation is off for this test (it measures frame times)" << std::endl;
    }
    desc.messageCallback = [log = log_](rhi::MessageSeverity severity, std::string_view message) {
        if (severity == rhi::MessageSeverity::Info) {
            // The backend's own notes ("D3D12: debug layer unavailable"): shown, never a failure.
            std::cout << "[ info ] " << message << std::endl;
            return;
        }
        const char* level = severity == rhi::MessageSeverity::Error ? "error" : "warning";
        std::lock_guard lock(log->mutex);
        log->messages.push_back(std::string(level) + ": " + std::string(message));
    };
    device_ = app::createDevice(api, desc);
    shaders_ = std::make_unique<rhi::ShaderLibrary>(*device_);
}

void GpuTestFixture::TearDown() {
    // Leak and lifetime checks report while the device is destroyed: destroy it first.
    shaders_.reset();
    device_.reset();
    const std::vector<std::string> messages = validationMessages();
    if (!messages.empty() && !expectMessages_) {
        std::ostringstream report;
        report << messages.size() << " validation message(s):";
        for (const std::string& message : messages) {
            report << "\n  " << message;
        }
        ADD_FAILURE() << report.str();
    }
}

rhi::IDevice& GpuTestFixture::device() {
    if (!device_) {
        throw rhi::Error("GpuTestFixture: no device (openDevice was not called)");
    }
    return *device_;
}

rhi::ShaderLibrary& GpuTestFixture::shaders() {
    if (!shaders_) {
        throw rhi::Error("GpuTestFixture: no shader library (openDevice was not called)");
    }
    return *shaders_;
}

std::string GpuTestFixture::kernelsUnavailable() {
    if (device().api() != rhi::Api::D3D12) {
        return {};
    }
    const rhi::ShaderFormat format = device().capabilities().shaderFormat;
    // A shader-model-6 device takes DXIL and DXBC; the others DXBC only.
    std::error_code error;
    for (std::filesystem::recursive_directory_iterator it(shaders().directory(), error), end;
         !error && it != end; it.increment(error)) {
        const auto extension = it->path().extension();
        if (extension == ".dxbc" || (extension == ".dxil" && format == rhi::ShaderFormat::Dxil)) {
            return {};
        }
    }
    if (format == rhi::ShaderFormat::Dxbc) {
        return "no DXBC kernels in " + shaders().directory().string() +
               " (this device takes DXBC only; the build found no vkd3d-compiler: .ci/install-dxbc-tools.sh)";
    }
    return "no DXIL or DXBC kernels in " + shaders().directory().string() +
           " (the build found neither DXC nor vkd3d-compiler)";
}

std::string GpuTestFixture::kernelUnavailable(std::string_view name) {
    if (device().api() != rhi::Api::D3D12) {
        return {};
    }
    return shaders().unavailableReason(name);
}

std::vector<std::string> GpuTestFixture::validationMessages() const {
    std::lock_guard lock(log_->mutex);
    return log_->messages;
}

void GpuTestFixture::submitAndWait(rhi::ICommandList& list) {
    rhi::IQueue& queue = device().queue(list.queueType());
    queue.waitForValue(queue.submit(list));
}

ComputeKernel GpuTestFixture::loadComputeKernel(std::string_view name,
                                                std::vector<rhi::BindingLayoutItem> items,
                                                uint32_t pushConstantBytes) {
    ComputeKernel kernel;
    kernel.layout = device().createBindingLayout(
        {.space = 0, .visibility = rhi::ShaderStageMask::Compute, .items = std::move(items)});
    kernel.pipeline = device().createComputePipeline({.shader = shaders().get(name),
                                                      .layouts = {kernel.layout},
                                                      .pushConstantBytes = pushConstantBytes,
                                                      .debugName = std::string(name)});
    return kernel;
}

std::string apiName(const ::testing::TestParamInfo<rhi::Api>& info) {
    return std::string(rhi::apiName(info.param));
}

} // namespace lumina::test
