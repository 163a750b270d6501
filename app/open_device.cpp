#include <iostream>

#include "app/backends.h"
#include "app/command.h"
#include "rhi/error.h"

namespace lumina::app {

rhi::DeviceHandle openDevice(const CommonOptions& options, bool presentation) {
    const auto adapters = listAdapters(options.api);
    if (adapters.empty()) {
        throw rhi::Error("no " + std::string(rhi::apiName(options.api)) + " adapter found" +
                         (options.api == rhi::Api::Vulkan ? " (install mesa-vulkan-drivers for lavapipe)" : ""));
    }
    if (options.deviceIndex >= adapters.size()) {
        throw UsageError("--device " + std::to_string(options.deviceIndex) + ": only " +
                         std::to_string(adapters.size()) + " adapter(s); see --list-devices");
    }
    rhi::DeviceDesc desc;
    desc.adapterIndex = options.deviceIndex;
    desc.validation = options.validation;
    desc.synchronizationValidation = options.validation;
    desc.presentation = presentation;
    desc.messageCallback = [](rhi::MessageSeverity severity, std::string_view message) {
        std::cerr << (severity == rhi::MessageSeverity::Error ? "validation error: " : "validation: ") << message
                  << '\n';
    };
    return createDevice(options.api, desc);
}

} // namespace lumina::app
