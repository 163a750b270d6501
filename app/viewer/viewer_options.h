#pragma once
// `lumina-viewer SCENE [flags]`: the flags, their help and their parsing. The grammar is the
// `lumina` CLI's (app/cli.h): a bad flag or value is a UsageError, exit code 2.
#include "app/cli.h"
#include "gi/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lumina::app::viewer {

struct ViewerOptions {
    std::string scene;
    CommonOptions common;  // --api, --device, --size (render and window size), --frames, --validation
    std::string technique; // empty: the scene's, else lumen; "auto" until main() chooses
    // --technique auto: the flags its calibration reads (chooseAutoTechnique, app/commands/).
    std::optional<ParsedArgs> autoTechnique;
    std::string preset; // empty: the scene's, else medium
    float exposureEv = 0.0f;
    bool exposureSet = false; // --exposure given: saved settings do not replace it
    bool vsync = true;
    bool vsyncSet = false; // --no-vsync given
    // --settings PATH (empty: the default place, app/viewer/viewer_settings.h).
    std::filesystem::path settingsPath;
    // From the saved settings (viewer_settings.h): the camera of the same scene, and whether
    // `view` came from them (a view the technique lacks is then skipped, not an error).
    std::optional<scene::Camera> camera;
    bool viewFromSettings = false;
    uint32_t framesInFlight = 2;
    // --screenshot-after N PATH: render N frames, write PATH (.png or .exr), exit.
    std::optional<uint32_t> screenshotAfter;
    std::filesystem::path screenshotPath;
    std::string view;              // empty: the final image
    bool screenshotWindow = false; // screenshots of the back buffer (UI included)
    // Resizes the window and minimises it once during the first frames (tests).
    bool testResize = false;
    bool cycleViews = false;
    bool testEdits = false; // switches technique and preset and edits a light during the first frames
    bool hotReload = true;  // recompile kernels whose HLSL file is saved
    // Checks hot reload by editing a copy of the kernels under this folder (tests; empty: off).
    std::filesystem::path testHotReload;
    bool help = false;
};

// Throws UsageError for anything wrong, naming the flag.
ViewerOptions parseViewerOptions(const std::vector<std::string>& args);
void printViewerHelp();

} // namespace lumina::app::viewer
