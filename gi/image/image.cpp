#include "gi/image/image.h"

#include <algorithm>
#include <utility>

namespace lumina::image {

namespace {

void checkSize(uint32_t width, uint32_t height) {
    if (width == 0 || height == 0 || width > kMaxImageSide || height > kMaxImageSide ||
        uint64_t(width) * height > kMaxImagePixels) {
        throw ImageError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                         " is outside 1..65536 per side and 2^28 pixels");
    }
}

} // namespace

Image::Image(uint32_t width, uint32_t height, std::vector<std::string> channelNames) {
    checkSize(width, height);
    width_ = width;
    height_ = height;
    for (std::string& name : channelNames) {
        addChannel(std::move(name));
    }
}

Image Image::rgba(uint32_t width, uint32_t height) {
    Image image(width, height, {"R", "G", "B"});
    image.addChannel("A", 1.0f);
    return image;
}

std::vector<std::string> Image::channelNames() const {
    std::vector<std::string> names;
    names.reserve(channels_.size());
    for (const Channel& channel : channels_) {
        names.push_back(channel.name);
    }
    return names;
}

const Image::Channel* Image::find(std::string_view name) const {
    const auto it = std::find_if(channels_.begin(), channels_.end(),
                                 [&](const Channel& channel) { return channel.name == name; });
    return it == channels_.end() ? nullptr : &*it;
}

Image::Channel* Image::find(std::string_view name) {
    return const_cast<Channel*>(std::as_const(*this).find(name));
}

std::span<float> Image::channel(std::string_view name) {
    Channel* found = find(name);
    if (!found) {
        throw ImageError("image has no channel '" + std::string(name) + "'");
    }
    return found->data;
}

std::span<const float> Image::channel(std::string_view name) const {
    const Channel* found = find(name);
    if (!found) {
        throw ImageError("image has no channel '" + std::string(name) + "'");
    }
    return found->data;
}

std::span<float> Image::addChannel(std::string name, float fill) {
    if (name.empty()) {
        throw ImageError("image channel names cannot be empty");
    }
    if (find(name)) {
        throw ImageError("image already has a channel '" + name + "'");
    }
    if (width_ == 0) {
        throw ImageError("cannot add channel '" + name + "' to an empty image");
    }
    channels_.push_back({std::move(name), std::vector<float>(pixelCount(), fill)});
    return channels_.back().data;
}

bool Image::removeChannel(std::string_view name) {
    const auto it = std::find_if(channels_.begin(), channels_.end(),
                                 [&](const Channel& channel) { return channel.name == name; });
    if (it == channels_.end()) {
        return false;
    }
    channels_.erase(it);
    return true;
}

size_t Image::index(uint32_t x, uint32_t y) const {
    if (x >= width_ || y >= height_) {
        throw ImageError("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                         sizeString(*this) + " image");
    }
    return size_t(y) * width_ + x;
}

float Image::at(std::string_view name, uint32_t x, uint32_t y) const {
    return channel(name)[index(x, y)];
}

void Image::set(std::string_view name, uint32_t x, uint32_t y, float value) {
    channel(name)[index(x, y)] = value;
}

Rgb Image::rgbAt(uint32_t x, uint32_t y) const {
    const size_t i = index(x, y);
    return {channel("R")[i], channel("G")[i], channel("B")[i]};
}

void Image::setRgb(uint32_t x, uint32_t y, Rgb value) {
    const size_t i = index(x, y);
    channel("R")[i] = value.r;
    channel("G")[i] = value.g;
    channel("B")[i] = value.b;
}

void Image::fillRgb(Rgb value) {
    std::ranges::fill(channel("R"), value.r);
    std::ranges::fill(channel("G"), value.g);
    std::ranges::fill(channel("B"), value.b);
}

std::string sizeString(const Image& image) {
    return std::to_string(image.width()) + "x" + std::to_string(image.height());
}

void requireSameSize(const Image& a, const Image& b, std::string_view what) {
    if (!a.sameSize(b)) {
        throw ImageError(std::string(what) + ": image sizes differ (" + sizeString(a) + " vs " +
                         sizeString(b) + ")");
    }
}

} // namespace lumina::image
