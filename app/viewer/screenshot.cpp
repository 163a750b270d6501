#include "app/viewer/screenshot.h"

#include "gi/deferred/buffer_readback.h"
#include "gi/image/exr.h"
#include "gi/image/png.h"

#include <stdexcept>

namespace lumina::app::viewer {

void writeScreenshot(rhi::IDevice& device, const gi::FrameRenderer& renderer, rhi::ITexture& shown,
                     const std::filesystem::path& path) {
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path());
    }
    if (path.extension() == ".exr") {
        image::Image hdr = gi::readTextureImage(device, *renderer.deferred().hdr());
        hdr.removeChannel("A");
        image::writeExr(path, hdr);
    } else if (path.extension() == ".png") {
        image::writeDisplayPng(path, gi::displayImage(gi::readTextureImage(device, shown)));
    } else {
        throw std::invalid_argument("screenshot " + path.string() + ": the name must end in .png or .exr");
    }
}

void writeWindowScreenshot(rhi::IDevice& device, rhi::ITexture& backbuffer,
                           const std::filesystem::path& path) {
    if (path.extension() != ".png") {
        throw std::invalid_argument("window screenshot " + path.string() +
                                    ": the window is written as .png only");
    }
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path());
    }
    image::writeDisplayPng(path, gi::displayImage(gi::readTextureImage(device, backbuffer)));
}

} // namespace lumina::app::viewer
