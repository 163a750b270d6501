#pragma once
// Loads compiled kernels by name ("rhi_tests/fill_pattern", "deferred/gbuffer.vsMain") from
// the build's shader folder, in the bytecode format the device takes, and caches them.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "rhi/device.h"

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

private:
    IDevice& device_;
    std::filesystem::path directory_;
    std::map<std::string, ShaderHandle, std::less<>> cache_;
};

} // namespace lumina::rhi
