#include "gi/frame/indirect_term.h"

#include "gi/deferred/buffer_readback.h"

#include <algorithm>
#include <string>

namespace lumina::gi {

image::Image indirectRadiance(const image::Image& irradiance, const image::Image& albedo, float scale) {
    if (!irradiance.sameSize(albedo)) {
        throw image::ImageError("indirect radiance: irradiance is " + std::to_string(irradiance.width()) +
                                "x" + std::to_string(irradiance.height()) + ", albedo " +
                                std::to_string(albedo.width()) + "x" + std::to_string(albedo.height()));
    }
    image::Image radiance = image::Image::rgb(irradiance.width(), irradiance.height());
    for (const char* c : {"R", "G", "B"}) {
        std::ranges::transform(irradiance.channel(c), albedo.channel(c), radiance.channel(c).begin(),
                               [scale](float e, float a) { return scale * e * a; });
    }
    return radiance;
}

image::Image readIndirectRadiance(rhi::IDevice& device, const FrameRenderer& renderer) {
    const rhi::TextureHandle irradiance = renderer.indirect();
    if (!irradiance) {
        return image::Image::rgb(renderer.deferred().width(), renderer.deferred().height());
    }
    return indirectRadiance(readTextureImage(device, *irradiance),
                            readTextureImage(device, *renderer.deferred().gbuffer().albedo),
                            renderer.indirectScale());
}

} // namespace lumina::gi
