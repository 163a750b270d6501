#pragma once
// A floating-point image with named channels, the CPU-side currency of references, test
// images, error maps and AOVs.
//
// Layout: planar. Each channel is one float plane of width*height values, row-major, with
// (0,0) at the top-left and index y*width + x (the EXR and PNG scanline order). Channel names
// follow OpenEXR: "R", "G", "B", "A", and layered extras such as "variance" or "albedo.R".
// Planar storage keeps any number of extra channels cheap and lets metrics walk one plane.
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::image {

// Every image and metric failure: the message names the file (or channel) and the problem.
class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Rgb {
    float r = 0.0f;
    float g = 0.0f;
    float b = 0.0f;
};

// Largest accepted side and pixel count: keeps a corrupt header from asking for terabytes.
inline constexpr uint32_t kMaxImageSide = 65536;
inline constexpr uint64_t kMaxImagePixels = uint64_t(1) << 28;

class Image {
public:
    Image() = default;
    // Zero-filled channels; throws ImageError on a zero or too large size or a repeated name.
    Image(uint32_t width, uint32_t height, std::vector<std::string> channelNames = {"R", "G", "B"});

    static Image rgb(uint32_t width, uint32_t height) { return Image(width, height, {"R", "G", "B"}); }
    // Alpha is filled with 1.
    static Image rgba(uint32_t width, uint32_t height);

    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    size_t pixelCount() const { return size_t(width_) * height_; }
    bool empty() const { return pixelCount() == 0; }
    bool sameSize(const Image& other) const { return width_ == other.width_ && height_ == other.height_; }

    // Channel names in storage order.
    std::vector<std::string> channelNames() const;
    size_t channelCount() const { return channels_.size(); }
    bool hasChannel(std::string_view name) const { return find(name) != nullptr; }
    bool hasRgb() const { return hasChannel("R") && hasChannel("G") && hasChannel("B"); }

    // The plane of a channel; ImageError naming the channel when it is absent.
    std::span<float> channel(std::string_view name);
    std::span<const float> channel(std::string_view name) const;
    // Appends a channel filled with `fill`; ImageError if the name exists or is empty.
    std::span<float> addChannel(std::string name, float fill = 0.0f);
    // Removes a channel if present; returns whether it was.
    bool removeChannel(std::string_view name);

    // One value, bounds-checked (ImageError outside the image).
    float at(std::string_view channel, uint32_t x, uint32_t y) const;
    void set(std::string_view channel, uint32_t x, uint32_t y, float value);

    // R, G, B of one pixel (ImageError without them or outside the image).
    Rgb rgbAt(uint32_t x, uint32_t y) const;
    void setRgb(uint32_t x, uint32_t y, Rgb value);
    // Every pixel's R, G, B set to `value`.
    void fillRgb(Rgb value);

private:
    struct Channel {
        std::string name;
        std::vector<float> data;
    };
    const Channel* find(std::string_view name) const;
    Channel* find(std::string_view name);
    size_t index(uint32_t x, uint32_t y) const;

    uint32_t width_ = 0;
    uint32_t height_ = 0;
    std::vector<Channel> channels_;
};

// "WxH", for messages.
std::string sizeString(const Image& image);

// ImageError unless both images have the same size; `what` names them, e.g. "ref.exr vs test.exr".
void requireSameSize(const Image& a, const Image& b, std::string_view what);

} // namespace lumina::image
