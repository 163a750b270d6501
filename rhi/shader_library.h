#pragma once
// Loads compiled kernels by name ("rhi_tests/fill_pattern", "deferred/gbuffer_visibility.vsMain") from
// the build's shader folder, in the bytecode format the device takes, and caches them.
// Each kernel picks its own file: SPIR-V on Vulkan; on D3D12 DXIL where the device has shader
// model 6 and the build made DXIL, else DXBC (docs/d3d12.md).
#include "rhi/device.h"

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

namespace lumina::rhi {

// $LUMINA_SHADER_DIR if set, else "shaders" beside the running executable or one level
// up, else the build tree's shader folder baked in at compile time.
std::filesystem::path defaultShaderDirectory();

class ShaderLibrary {
public:
    ShaderLibrary(IDevice& device, std::filesystem::path directory = defaultShaderDirectory());

    // The entry point is the part of the name after the last '.', or "main".
    ShaderHandle get(std::string_view name, ShaderStage stage = ShaderStage::Compute);
    const std::filesystem::path& directory() const { return directory_; }
    // Empty when `name` can be loaded on this device; else why not: no file in any format the
    // device takes, with the build's reason where it wrote one (<name>.dxbc.unavailable).
    std::string unavailableReason(std::string_view name) const;

private:
    // The file of the first format the device takes that the build made, or empty.
    std::filesystem::path locate(std::string_view name) const;

    IDevice& device_;
    std::filesystem::path directory_;
    std::map<std::string, ShaderHandle, std::less<>> cache_;
};

} // namespace lumina::rhi
