// lumina-viewer: the interactive viewer. `lumina-viewer --help` lists the flags and the keys;
// docs/viewer.md describes it.
#include "app/command.h"
#include "app/viewer/viewer.h"
#include "app/viewer/viewer_options.h"
#include "gi/scene/scene_loader.h"
#include "rhi/error.h"

#include <exception>
#include <iostream>

namespace {

constexpr int kExitUsage = 2;

int run(const std::vector<std::string>& args) {
    using namespace lumina;
    const app::viewer::ViewerOptions options = app::viewer::parseViewerOptions(args);
    if (options.help) {
        app::viewer::printViewerHelp();
        return 0;
    }
    scene::Scene scene = scene::loadScene(options.scene);
    if (options.common.size) {
        scene.image = {options.common.size->width, options.common.size->height};
    }
    rhi::DeviceHandle device = app::openDevice(options.common, /*presentation=*/true);
    std::cout << "device: " << device->adapter().name << " (" << rhi::apiName(device->api()) << ")\n"
              << "scene: " << scene.name << ", " << scene.image.width << "x" << scene.image.height << '\n';
    app::viewer::Viewer viewer(*device, options, std::move(scene));
    return viewer.run();
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const lumina::app::UsageError& error) {
        std::cerr << "lumina-viewer: " << error.what() << '\n';
        return kExitUsage;
    } catch (const std::exception& error) {
        std::cerr << "lumina-viewer: " << error.what() << '\n';
        return 1;
    }
}
