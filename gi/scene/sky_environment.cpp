#include "gi/scene/sky_environment.h"

#include "gi/image/exr.h"
#include "gi/scene/scene_error.h"
#include "shaders/common/constants_shared.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

namespace lumina::scene {

namespace {

std::string channelName(int c) {
    return c == 0 ? "R" : c == 1 ? "G" : "B";
}

glm::vec3 texel(const SkyEnvironment& sky, int x, int y) {
    const int w = int(sky.width);
    x = ((x % w) + w) % w; // longitude wraps
    y = std::clamp(y, 0, int(sky.height) - 1);
    return sky.radiance[size_t(y) * sky.width + size_t(x)];
}

} // namespace

SkyEnvironment readSkyEnvironment(const std::filesystem::path& file, float intensity) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) {
        throw SceneError(file, std::filesystem::exists(file, error) ? "sky environment: not a regular file"
                                                                    : "sky environment: no such file");
    }
    if (!std::isfinite(intensity) || intensity < 0.0f) {
        throw SceneError(file, "sky environment: intensity " + std::to_string(intensity) +
                                   " must be finite and not negative");
    }
    image::Image pixels;
    try {
        const image::ExrInfo info = image::readExrInfo(file);
        if (info.width == 0 || info.height == 0 || info.width > kMaxSkyWidth || info.height > kMaxSkyHeight ||
            uint64_t(info.width) * info.height > kMaxSkyTexels) {
            throw SceneError(file, "sky environment: " + std::to_string(info.width) + "x" +
                                       std::to_string(info.height) + " is empty or larger than " +
                                       std::to_string(kMaxSkyWidth) + "x" + std::to_string(kMaxSkyHeight) +
                                       " (at most 2^25 texels)");
        }
        pixels = image::readExr(file);
    } catch (const image::ImageError& e) {
        throw SceneError(file,
                         std::string("sky environment: not a readable RGB EXR image (") + e.what() + ")");
    }
    SkyEnvironment sky;
    sky.file = file;
    sky.width = pixels.width();
    sky.height = pixels.height();
    sky.intensity = intensity;
    sky.radiance.resize(size_t(sky.width) * sky.height);
    const std::span<const float> planes[3] = {pixels.channel("R"), pixels.channel("G"), pixels.channel("B")};
    for (size_t i = 0; i < sky.radiance.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const float value = planes[c][i];
            if (!std::isfinite(value) || value < 0.0f) {
                throw SceneError(file, "sky environment: texel (" + std::to_string(i % sky.width) + ", " +
                                           std::to_string(i / sky.width) + ") channel " + channelName(c) +
                                           " is " + std::to_string(value) +
                                           " (radiance must be finite and not negative)");
            }
            const float scaled = value * intensity;
            if (!std::isfinite(scaled)) {
                throw SceneError(file, "sky environment: intensity " + std::to_string(intensity) +
                                           " overflows texel (" + std::to_string(i % sky.width) + ", " +
                                           std::to_string(i / sky.width) + ")");
            }
            sky.radiance[i][c] = scaled;
        }
    }
    return sky;
}

glm::vec2 skyTexelCoordinates(const SkyEnvironment& sky, const glm::vec3& direction) {
    const float u = 0.5f + std::atan2(direction.x, -direction.z) / (2.0f * LUMINA_PI);
    const float v = std::acos(std::clamp(direction.y, -1.0f, 1.0f)) / LUMINA_PI;
    return {u * float(sky.width), v * float(sky.height)};
}

glm::vec3 skyRadiance(const Scene& scene, const glm::vec3& direction) {
    if (!scene.skyEnvironment) {
        return scene.sky;
    }
    const SkyEnvironment& sky = *scene.skyEnvironment;
    const glm::vec2 p = skyTexelCoordinates(sky, direction) - 0.5f; // texel centres at +0.5
    const glm::vec2 base = glm::floor(p);
    const glm::vec2 f = p - base;
    const int x = int(base.x), y = int(base.y);
    return glm::mix(glm::mix(texel(sky, x, y), texel(sky, x + 1, y), f.x),
                    glm::mix(texel(sky, x, y + 1), texel(sky, x + 1, y + 1), f.x), f.y);
}

} // namespace lumina::scene
