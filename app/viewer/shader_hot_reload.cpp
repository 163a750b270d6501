#include "app/viewer/shader_hot_reload.h"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace lumina::app::viewer {

namespace {

constexpr std::chrono::milliseconds kPollInterval{500};

struct KernelDeclaration {
    std::string stage; // cs, vs, ps
    std::string entry;
};

std::vector<KernelDeclaration> declarations(const std::filesystem::path& source) {
    static const std::regex kDeclaration(R"(^// lumina-kernel: ([a-z][a-z]) ([A-Za-z_][A-Za-z0-9_]*))");
    std::vector<KernelDeclaration> found;
    std::ifstream file(source);
    std::string line;
    std::smatch match;
    while (std::getline(file, line)) {
        if (std::regex_search(line, match, kDeclaration)) {
            found.push_back({match[1], match[2]});
        }
    }
    return found;
}

std::string glslangStage(const std::string& stage) {
    return stage == "vs" ? "vert" : stage == "ps" ? "frag" : "comp";
}

std::string quoted(const std::filesystem::path& path) {
    return "'" + path.string() + "'";
}

// Runs `command` through the shell; its output (both streams) goes to `log`.
bool runLogged(const std::string& command, const std::filesystem::path& log, std::string& output) {
    const int rc = std::system((command + " > " + quoted(log) + " 2>&1").c_str());
    std::ifstream in(log);
    std::ostringstream text;
    text << in.rdbuf();
    output += text.str();
    return rc == 0;
}

} // namespace

std::optional<KernelCompiler> buildKernelCompiler(const std::filesystem::path& outputRoot) {
#if defined(LUMINA_HOT_RELOAD_GLSLANG)
    KernelCompiler compiler;
    compiler.glslang = LUMINA_HOT_RELOAD_GLSLANG;
    compiler.spirvVal = LUMINA_HOT_RELOAD_SPIRV_VAL;
    compiler.sourceRoot = LUMINA_HOT_RELOAD_SOURCE_DIR;
    compiler.outputRoot = outputRoot;
    compiler.shiftT = LUMINA_HOT_RELOAD_SHIFT_T;
    compiler.shiftU = LUMINA_HOT_RELOAD_SHIFT_U;
    compiler.shiftS = LUMINA_HOT_RELOAD_SHIFT_S;
    if (std::filesystem::is_directory(compiler.sourceRoot) && std::filesystem::exists(compiler.glslang)) {
        return compiler;
    }
#else
    (void)outputRoot;
#endif
    return std::nullopt;
}

ShaderHotReload::ShaderHotReload(KernelCompiler compiler) : compiler_(std::move(compiler)) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(compiler_.sourceRoot)) {
        if (entry.path().extension() == ".hlsl") {
            seen_[entry.path()] = entry.last_write_time();
        }
    }
}

bool ShaderHotReload::poll() {
    const auto now = std::chrono::steady_clock::now();
    if (now - lastPoll_ < kPollInterval) {
        return false;
    }
    lastPoll_ = now;
    bool replaced = false;
    std::error_code error;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(compiler_.sourceRoot, error)) {
        if (entry.path().extension() != ".hlsl") {
            continue;
        }
        const auto written = entry.last_write_time(error);
        auto [it, inserted] = seen_.try_emplace(entry.path(), written);
        if (!inserted && it->second != written) {
            it->second = written;
            replaced |= recompile(entry.path());
        }
    }
    return replaced;
}

bool ShaderHotReload::recompile(const std::filesystem::path& source) {
    const std::filesystem::path relative = std::filesystem::relative(source, compiler_.sourceRoot);
    const std::string stem =
        relative.generic_string().substr(0, relative.generic_string().size() - 5); // .hlsl
    const std::vector<KernelDeclaration> kernels = declarations(source);
    // Every entry point compiles and validates into a temporary file first: either all of the
    // file's kernels are replaced, or none.
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> ready;
    std::string output;
    for (const KernelDeclaration& kernel : kernels) {
        const std::string name = kernel.entry == "main" ? stem : stem + "." + kernel.entry;
        const std::filesystem::path target = compiler_.outputRoot / (name + ".spv");
        const std::filesystem::path temporary = compiler_.outputRoot / (name + ".spv.reload");
        const std::filesystem::path log = compiler_.outputRoot / (name + ".spv.reload.log");
        std::filesystem::create_directories(target.parent_path());
        std::ostringstream command;
        command << quoted(compiler_.glslang) << " -D -V --target-env vulkan1.1 --hlsl-iomap -S "
                << glslangStage(kernel.stage) << " -e " << kernel.entry << " -I"
                << quoted(compiler_.sourceRoot)
                << " -DLUMINA_SPIRV=1 --shift-cbuffer-binding 0 --shift-texture-binding " << compiler_.shiftT
                << " --shift-UAV-binding " << compiler_.shiftU << " --shift-sampler-binding "
                << compiler_.shiftS << " -o " << quoted(temporary) << ' ' << quoted(source);
        const bool ok = runLogged(command.str(), log, output) &&
                        runLogged(quoted(compiler_.spirvVal) + " --target-env vulkan1.1 " + quoted(temporary),
                                  log, output);
        std::filesystem::remove(log);
        if (!ok) {
            for (const auto& [from, to] : ready) {
                std::filesystem::remove(from);
            }
            std::filesystem::remove(temporary);
            error_ = relative.generic_string() + " (" + name + "):\n" + output;
            message_ = "kept the old kernels of " + relative.generic_string() + ": it does not compile";
            return false;
        }
        ready.emplace_back(temporary, target);
    }
    for (const auto& [from, to] : ready) {
        std::filesystem::rename(from, to);
    }
    error_.clear();
    message_ = "reloaded " + relative.generic_string() + ": " + std::to_string(ready.size()) + " kernel(s)";
    return !ready.empty();
}

} // namespace lumina::app::viewer
