#pragma once
// Shader hot reload: when a kernel's HLSL file is saved, its entry points (the
// `// lumina-kernel:` declarations) are compiled again with the build's compiler and flags
// (glslangValidator with --hlsl-iomap and the register shifts, then spirv-val, as
// cmake/LuminaShaders.cmake does) into the build's shader folder, and the caller drops its
// pipelines so the next frame loads the new kernels. A kernel that fails to compile or validate
// replaces nothing: the old one keeps running and the error is kept for the UI.
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace lumina::app::viewer {

struct KernelCompiler {
    std::filesystem::path glslang;
    std::filesystem::path spirvVal;
    std::filesystem::path sourceRoot; // shaders/ of the source tree
    std::filesystem::path outputRoot; // the build's shader folder
    int shiftT = 100, shiftU = 200, shiftS = 300;
};

// The build's compiler, where this build compiled SPIR-V with glslang; none otherwise (DXC
// builds, or a source tree that is not there any more).
std::optional<KernelCompiler> buildKernelCompiler(const std::filesystem::path& outputRoot);

class ShaderHotReload {
public:
    explicit ShaderHotReload(KernelCompiler compiler);

    // Looks at the HLSL files' modification times (at most twice a second) and recompiles those
    // that changed since the last look. True when kernels were replaced.
    bool poll();
    // The compiler's output for the last file that failed; empty after a success.
    const std::string& error() const { return error_; }
    // What the last reload did ("reloaded deferred/composite.hlsl: 1 kernel").
    const std::string& message() const { return message_; }

private:
    bool recompile(const std::filesystem::path& source);

    KernelCompiler compiler_;
    std::map<std::filesystem::path, std::filesystem::file_time_type> seen_;
    std::chrono::steady_clock::time_point lastPoll_{};
    std::string error_;
    std::string message_;
};

} // namespace lumina::app::viewer
