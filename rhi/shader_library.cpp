#include "rhi/shader_library.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

#include "rhi/error.h"

#if defined(_WIN32)
#include <windows.h>
#endif

namespace lumina::rhi {

namespace {

std::filesystem::path executableDirectory() {
#if defined(_WIN32)
    wchar_t buffer[MAX_PATH];
    const DWORD length = GetModuleFileNameW(nullptr, buffer, MAX_PATH);
    return length ? std::filesystem::path(std::wstring(buffer, length)).parent_path() : std::filesystem::path();
#else
    std::error_code error;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : exe.parent_path();
#endif
}

std::string_view extensionFor(ShaderFormat format) {
    switch (format) {
    case ShaderFormat::Spirv: return ".spv";
    case ShaderFormat::Dxil: return ".dxil";
    case ShaderFormat::Dxbc: return ".dxbc";
    }
    return ".bin";
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

ShaderHandle ShaderLibrary::get(std::string_view name, ShaderStage stage) {
    if (const auto it = cache_.find(name); it != cache_.end()) {
        return it->second;
    }
    const auto path = directory_ / (std::string(name) + std::string(extensionFor(device_.capabilities().shaderFormat)));
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw Error("kernel '" + std::string(name) + "' not found: cannot open " + path.string() +
                    " (set LUMINA_SHADER_DIR to the build's shaders folder)");
    }
    const std::vector<uint8_t> bytecode((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
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
