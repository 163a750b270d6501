#include "app/viewer/viewer_options.h"

#include "app/commands/auto_technique_option.h"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <string_view>

namespace lumina::app::viewer {

namespace {

// The common flags the viewer takes (app/cli.cpp parses them for every tool alike).
constexpr std::string_view kCommonUsed[] = {"help", "api", "device", "size", "frames", "validation"};

const std::vector<FlagSpec>& viewerFlags() {
    static const std::vector<FlagSpec> flags = withAutoTechniqueFlags({
        {"technique", "NAME",
         "GI technique to start with: direct, lumen, ddgi or sh-grid (default: the scene's, else lumen), or "
         "auto with --error-budget E: the cheapest technique and preset whose calibrated relMSE on this "
         "scene is at most E (docs/measurement.md), chosen before the window opens"},
        {"preset", "NAME",
         "quality preset to start with: low, medium or high (default: the scene's, else medium)"},
        {"exposure", "EV", "exposure in stops before the tonemap (default 0)"},
        {"no-vsync", "", "present without waiting for vertical blank (mailbox or immediate)"},
        {"frames-in-flight", "N", "frames the CPU may queue ahead of the display: 2 or 3 (default 2)"},
        {"screenshot-after", "N PATH", "render N frames, write the frame to PATH (.png or .exr), exit"},
        {"view", "NAME", "start on a debug view, by its name in the view menu (e.g. 'gbuffer: normal')"},
        {"settings", "PATH",
         "where the settings (technique, preset, exposure, vsync, view, camera) are read at start and "
         "saved at exit, also when the GPU is lost or out of memory (default: "
         "$XDG_CONFIG_HOME/lumina/viewer.json or ~/.config/lumina/viewer.json; runs with --frames, "
         "--screenshot-after or a test flag use none unless given)"},
        {"screenshot-window", "", "screenshots show the window, UI included, instead of the rendered frame"},
        {"no-hot-reload", "",
         "do not recompile a kernel when its HLSL file is saved (SPIR-V builds with glslang)"},
        {"test-resize", "", "resize, minimise and restore the window during the first frames (tests)"},
        {"test-edits", "",
         "switch technique and preset, edit a light and turn the slice views' axis during the first "
         "frames (tests)"},
        {"cycle-views", "", "show the next debug view every frame (tests: every view once)"},
        {"test-hot-reload", "DIR",
         "edit a copy of the kernels under DIR while running and check each edit is reloaded, and a "
         "syntax error reported with the old kernel kept; exit 0 when both hold (tests)"},
    });
    return flags;
}

const FlagSpec* commonFlag(std::string_view name) {
    for (const FlagSpec& flag : commonFlags()) {
        if (flag.name == name) {
            return &flag;
        }
    }
    return nullptr;
}

// The common flags whose meaning in the viewer needs its own words.
FlagSpec viewerMeaning(const FlagSpec& flag) {
    if (flag.name == "device") {
        return {flag.name, flag.valueName, "adapter index from `lumina --list-devices` (default 0)"};
    }
    if (flag.name == "size") {
        return {flag.name, flag.valueName,
                "render size and first window size (default: the scene's image size)"};
    }
    if (flag.name == "frames") {
        return {flag.name, flag.valueName, "exit after N frames (default: run until the window is closed)"};
    }
    if (flag.name == "validation") {
        return {flag.name, flag.valueName,
                "enable the API's validation layer; any message makes the exit code 1"};
    }
    return flag;
}

void printFlag(const FlagSpec& flag) {
    const std::string left =
        "  --" + std::string(flag.name) + (flag.valueName.empty() ? "" : " ") + std::string(flag.valueName);
    std::cout << std::left << std::setw(28) << left << ' ' << flag.help << '\n';
}

} // namespace

void printViewerHelp() {
    std::cout
        << "usage: lumina-viewer SCENE [flags]\n\n"
           "Opens SCENE (a built-in name such as cornell_box, or a .json, .gltf or .glb path) in a window\n"
           "and renders it in real time with the GI technique of `lumina render`. The image is rendered at\n"
           "--size (default: the scene's image size) and scaled to fit the window.\n\n"
           "keys:\n"
           "  W A S D, Q E              fly forward, left, back, right, down, up (Shift: 4x faster)\n"
           "  right mouse button + move look around; the mouse wheel changes the fly speed\n"
           "  C                         print the camera as scene-file JSON\n"
           "  F12                       screenshot: lumina-viewer-N.png and .exr in the working directory\n"
           "  [ and ]                   previous / next debug view (intermediate buffer); 0: final image\n"
           "  F1                        hide or show the UI\n"
           "  V                         vsync on or off\n"
           "  Escape                    quit\n\n"
           "flags:\n";
    for (std::string_view name : kCommonUsed) {
        printFlag(viewerMeaning(*commonFlag(name)));
    }
    for (const FlagSpec& flag : viewerFlags()) {
        printFlag(flag);
    }
    std::cout
        << "\nExit codes: 0 done, 1 an error (or a validation message with --validation), 2 a bad flag.\n";
}

ViewerOptions parseViewerOptions(const std::vector<std::string>& rawArgs) {
    ViewerOptions options;
    // --screenshot-after takes two values, which the shared grammar cannot say: taken out first.
    std::vector<std::string> args;
    for (size_t i = 0; i < rawArgs.size(); ++i) {
        if (rawArgs[i] == "--screenshot-after") {
            if (i + 2 >= rawArgs.size()) {
                throw UsageError("--screenshot-after needs two values: N (frames) and PATH");
            }
            options.screenshotAfter =
                static_cast<uint32_t>(parseUint("screenshot-after", rawArgs[i + 1], 1, 1'000'000));
            options.screenshotPath = rawArgs[i + 2];
            const auto extension = options.screenshotPath.extension();
            if (extension != ".png" && extension != ".exr") {
                throw UsageError("--screenshot-after: " + rawArgs[i + 2] + " must end in .png or .exr");
            }
            i += 2;
            continue;
        }
        args.push_back(rawArgs[i]);
    }

    std::vector<FlagSpec> extra = viewerFlags();
    std::erase_if(extra, [](const FlagSpec& flag) { return flag.name == "screenshot-after"; });
    const ParsedArgs parsed = parseArgs("lumina-viewer", args, extra);
    for (const FlagSpec& flag : commonFlags()) {
        const bool used =
            std::find(std::begin(kCommonUsed), std::end(kCommonUsed), flag.name) != std::end(kCommonUsed);
        if (!used && parsed.has(flag.name)) {
            throw UsageError("--" + std::string(flag.name) +
                             " is not a lumina-viewer flag (see lumina-viewer --help)");
        }
    }
    options.help = parsed.has("help");
    if (options.help) {
        return options;
    }
    if (parsed.positional.size() != 1) {
        throw UsageError("lumina-viewer takes one scene: a built-in name or a .json, .gltf or .glb path (see "
                         "lumina-viewer --help)");
    }
    options.scene = parsed.positional.front();
    options.common = parsed.common;
    options.technique = parsed.get("technique");
    if (options.technique == "auto") {
        options.autoTechnique = parsed;
    } else {
        requireAutoForAutoFlags(parsed);
    }
    options.preset = parsed.get("preset");
    options.exposureEv = static_cast<float>(parsed.getDouble("exposure", 0.0));
    options.exposureSet = parsed.has("exposure");
    options.vsync = !parsed.has("no-vsync");
    options.vsyncSet = parsed.has("no-vsync");
    options.settingsPath = parsed.get("settings");
    options.framesInFlight = static_cast<uint32_t>(parsed.getUint("frames-in-flight", 2, 2, 3));
    options.testResize = parsed.has("test-resize");
    options.hotReload = !parsed.has("no-hot-reload");
    options.view = parsed.get("view");
    options.cycleViews = parsed.has("cycle-views");
    options.testEdits = parsed.has("test-edits");
    options.screenshotWindow = parsed.has("screenshot-window");
    options.testHotReload = parsed.get("test-hot-reload");
    if (!options.testHotReload.empty() && !options.hotReload) {
        throw UsageError("--test-hot-reload tests hot reload: it cannot run with --no-hot-reload");
    }
    if (options.screenshotWindow && options.screenshotAfter && options.screenshotPath.extension() != ".png") {
        throw UsageError("--screenshot-window writes the window as .png only, not " +
                         options.screenshotPath.string());
    }
    return options;
}

} // namespace lumina::app::viewer
