// lumina-viewer: the interactive viewer. `lumina-viewer --help` lists the flags and the keys;
// docs/viewer.md describes it.
#include "app/command.h"
#include "app/commands/auto_technique_option.h"
#include "app/viewer/viewer.h"
#include "app/viewer/viewer_options.h"
#include "app/viewer/viewer_settings.h"
#include "gi/scene/scene_loader.h"
#include "rhi/error.h"
#include "rhi/out_of_memory_error.h"

#include <exception>
#include <iostream>

namespace {

constexpr int kExitUsage = 2;

int run(const std::vector<std::string>& args) {
    using namespace lumina;
    app::viewer::ViewerOptions options = app::viewer::parseViewerOptions(args);
    if (options.help) {
        app::viewer::printViewerHelp();
        return 0;
    }
    // Saved settings fill in what the flags leave open (app/viewer/viewer_settings.h).
    const std::optional<std::filesystem::path> settingsPath = app::viewer::viewerSettingsPath(options);
    if (settingsPath) {
        if (const auto saved = app::viewer::loadViewerSettings(*settingsPath)) {
            app::viewer::applySavedSettings(*saved, options);
            std::cout << "settings: read from " << settingsPath->string() << '\n';
        }
    }
    if (options.autoTechnique) {
        // Calibrated (or its cached table reused) on a device of its own, closed before the
        // window's opens; the choice replaces any saved technique and preset.
        const app::ParsedArgs chosen = app::chooseAutoTechnique(*options.autoTechnique);
        options.technique = chosen.get("technique");
        options.preset = chosen.get("preset");
    }
    scene::Scene scene = scene::loadScene(options.scene);
    if (options.common.size) {
        scene.image = {options.common.size->width, options.common.size->height};
    }
    rhi::DeviceHandle device = app::openDevice(options.common, /*presentation=*/true);
    std::cout << "device: " << device->adapter().name << " (" << rhi::apiName(device->api()) << ")\n"
              << "scene: " << scene.name << ", " << scene.image.width << "x" << scene.image.height << '\n';
    app::viewer::Viewer viewer(*device, options, std::move(scene), settingsPath);
    return viewer.run();
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const lumina::app::UsageError& error) {
        std::cerr << "lumina-viewer: " << error.what() << '\n';
        return kExitUsage;
    } catch (const lumina::rhi::OutOfMemoryError& error) {
        // The GPU memory the viewer's --size, technique and preset need, named by the RHI.
        std::cerr << "lumina-viewer: error: " << error.what()
                  << "\n  (a smaller --size, a lower --preset or a smaller scene needs less GPU memory)\n";
        return 1;
    } catch (const lumina::rhi::DeviceLostError& error) {
        std::cerr << "lumina-viewer: error: the GPU device was lost: " << error.what() << '\n';
        return 1;
    } catch (const std::exception& error) {
        std::cerr << "lumina-viewer: " << error.what() << '\n';
        return 1;
    }
}
