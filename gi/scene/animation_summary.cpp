#include "gi/scene/animation_summary.h"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace lumina::scene {

namespace {

std::string seconds(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g s", value);
    return text;
}

// "translation (5 keys, linear)"; nothing for an empty track.
template <typename T>
void describe(std::string& line, const char* what, const Keyframes<T>& track) {
    if (track.empty()) {
        return;
    }
    std::string mode = interpolationName(track.interpolation);
    for (char& c : mode) {
        c = char(std::tolower(static_cast<unsigned char>(c)));
    }
    line += std::string(line.back() == ':' ? " " : ", ") + what + " (" + std::to_string(track.times.size()) +
            (track.times.size() == 1 ? " key, " : " keys, ") + mode + ")";
}

// "1 light", "3 lights".
std::string count(size_t n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

template <typename T>
size_t tracks(const Keyframes<T>& track) {
    return track.empty() ? 0 : 1;
}

std::string clipLine(const NodeClip& clip, const SceneAnimation& animation) {
    std::string line = "glTF animation '" + clip.name + "', " + seconds(clip.length) + ":";
    for (size_t c = 0; c < clip.channels.size() && c < 4; ++c) {
        const NodeChannel& channel = clip.channels[c];
        const std::string what =
            "node '" + animation.nodes[channel.node].name + "' " + nodePropertyName(channel.property);
        if (channel.property == NodeProperty::Rotation) {
            describe(line, what.c_str(), channel.rotationKeys);
        } else {
            describe(line, what.c_str(), channel.vectorKeys);
        }
    }
    if (clip.channels.size() > 4) {
        line += ", ... " + std::to_string(clip.channels.size() - 4) + " more channels";
    }
    return line;
}

} // namespace

size_t animationTrackCount(const SceneAnimation& animation) {
    size_t count = 0;
    for (const NodeClip& clip : animation.clips) {
        count += clip.channels.size();
    }
    for (const InstancePath& path : animation.instancePaths) {
        count += tracks(path.translation) + tracks(path.rotation);
    }
    for (const LightPath& path : animation.lightPaths) {
        count += tracks(path.position) + tracks(path.direction) + tracks(path.sunDegrees) +
                 tracks(path.color) + tracks(path.intensity) + tracks(path.on);
    }
    for (const MaterialPath& path : animation.materialPaths) {
        count += tracks(path.emission) + tracks(path.on);
    }
    return count;
}

std::vector<std::string> animationSummary(const Scene& scene, size_t maxLines) {
    const SceneAnimation& animation = scene.animation;
    if (animation.empty()) {
        return {"none"};
    }
    const double length = animation.length();
    const bool loops = animation.scriptLoopSeconds > 0.0 || !animation.clips.empty();
    char fps[32];
    std::snprintf(fps, sizeof(fps), "%g", double(scene.framesPerSecond));
    std::vector<std::string> lines = {count(animationTrackCount(animation), "track") + " on " +
                                      count(animation.animatedInstances().size(), "instance") + ", " +
                                      count(animation.animatedLights().size(), "light") + ", " +
                                      count(animation.animatedMaterials().size(), "material") + "; " +
                                      (loops ? "loops every " : "ends at ") + seconds(length) + " (" +
                                      std::to_string(std::llround(length * scene.framesPerSecond)) +
                                      " frames at " + fps + " per second)"};
    std::vector<std::string> rest;
    for (const NodeClip& clip : animation.clips) {
        rest.push_back(clipLine(clip, animation));
    }
    for (const InstancePath& path : animation.instancePaths) {
        std::string line = "object '" + scene.instances[path.instance].name + "':";
        describe(line, "translation", path.translation);
        describe(line, "rotation", path.rotation);
        rest.push_back(line);
    }
    for (const LightPath& path : animation.lightPaths) {
        std::string line = "light '" + scene.lights[path.light].name + "':";
        describe(line, "position", path.position);
        describe(line, "direction", path.direction);
        describe(line, "sun path", path.sunDegrees);
        describe(line, "colour", path.color);
        describe(line, "intensity", path.intensity);
        describe(line, "on/off", path.on);
        rest.push_back(line);
    }
    for (const MaterialPath& path : animation.materialPaths) {
        std::string line = "material '" + scene.materials[path.material].name + "':";
        describe(line, "emission", path.emission);
        describe(line, "on/off", path.on);
        rest.push_back(line);
    }
    for (size_t i = 0; i < rest.size(); ++i) {
        if (lines.size() + 1 >= maxLines && i + 1 < rest.size()) {
            lines.push_back("... and " + std::to_string(rest.size() - i) + " more");
            break;
        }
        lines.push_back(rest[i]);
    }
    return lines;
}

} // namespace lumina::scene
