#include "rhi/shader_library.h"

#include "rhi/error.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#if defined(_WIN32)
#include <windows.h>
#endif

namespace lumina::rhi {

namespace {

std::filesystem::path executableDirectory() {
#if defined(_WIN32)
    wchar_t buffer[MAX_PATH];
    const DWORD length = GetModuleFileNameW(nullptr, buffer, MAX_PATH);
    return length ? std::filesystem::path(std::wstring(buffer, length)).parent_path()
                  : std::filesystem::path();
#else
    std::error_code error;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : exe.parent_path();
#endif
}

std::string_view extensionFor(ShaderFormat format) {
    switch (format) {
    case ShaderFormat::Spirv:
        return ".spv";
    case ShaderFormat::Dxil:
        return ".dxil";
    case ShaderFormat::Dxbc:
        return ".dxbc";
    }
    return ".bin";
}

// The formats a device takes, best first. A D3D12 device with shader model 6 (DXIL) runs
// DXBC too, so a kernel the build made only as DXBC still loads there.
std::vector<ShaderFormat> acceptedFormats(ShaderFormat deviceFormat) {
    if (deviceFormat == ShaderFormat::Dxil) {
        return {ShaderFormat::Dxil, ShaderFormat::Dxbc};
    }
    return {deviceFormat};
}

} // namespace

std::filesystem::path defaultShaderDirectory() {
    if (const char* env = std::getenv("LUMINA_SHADER_DIR"); env && *env) {
        return env;
    }
    const auto exeDir = executableDirectory();
    for (const auto& candidate : {exeDir / "shaders", exeDir.parent_path() / "shaders"}) {
        if (!exeDir.empty() && std::filesystem::is_directory(candidate)) {
            return candidate;
        }
    }
    return LUMINA_BUILD_SHADER_DIR;
}

ShaderLibrary::ShaderLibrary(IDevice& device, std::filesystem::path directory)
    : device_(device), directory_(std::move(directory)) {}

std::filesystem::path ShaderLibrary::locate(std::string_view name) const {
    for (const ShaderFormat format : acceptedFormats(device_.capabilities().shaderFormat)) {
        auto path = directory_ / (std::string(name) + std::string(extensionFor(format)));
        if (std::filesystem::is_regular_file(path)) {
            return path;
        }
    }
    return {};
}

std::string ShaderLibrary::unavailableReason(std::string_view name) const {
    if (!locate(name).empty()) {
        return {};
    }
    std::string tried;
    for (const ShaderFormat format : acceptedFormats(device_.capabilities().shaderFormat)) {
        const std::string file = std::string(name) + std::string(extensionFor(format));
        tried += (tried.empty() ? "" : " or ") + file;
        // The build's reason for not making this kernel in this format, one line.
        std::ifstream reasonFile(directory_ / (file + ".unavailable"));
        if (std::string reason; reasonFile && std::getline(reasonFile, reason) && !reason.empty()) {
            return "kernel '" + std::string(name) + "' has no " + file + ": " + reason;
        }
    }
    return "kernel '" + std::string(name) + "' not found: no " + tried + " in " + directory_.string() +
           " (set LUMINA_SHADER_DIR to the build's shaders folder)";
}

ShaderHandle ShaderLibrary::get(std::string_view name, ShaderStage stage) {
    if (const auto it = cache_.find(name); it != cache_.end()) {
        return it->second;
    }
    const auto path = locate(name);
    if (path.empty()) {
        throw Error(unavailableReason(name));
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw Error("kernel '" + std::string(name) + "': cannot open " + path.string());
    }
    const std::vector<uint8_t> bytecode((std::istreambuf_iterator<char>(file)),
                                        std::istreambuf_iterator<char>());
    if (bytecode.empty()) {
        throw Error("kernel '" + std::string(name) + "' is empty: " + path.string());
    }
    ShaderDesc desc;
    desc.stage = stage;
    const auto dot = name.rfind('.');
    desc.entryPoint = dot == std::string_view::npos ? "main" : std::string(name.substr(dot + 1));
    desc.debugName = std::string(name);
    ShaderHandle shader = device_.createShader(desc, bytecode);
    cache_.emplace(std::string(name), shader);
    return shader;
}

} // namespace lumina::rhi
