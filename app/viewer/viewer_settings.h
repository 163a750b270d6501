#pragma once
// What the viewer keeps from one run to the next (docs/viewer.md#settings): the technique,
// preset, exposure, vsync, debug view and, for the same scene, the camera. Saved when the
// viewer exits, on a normal close and when the GPU is lost or out of memory (so a crash of the
// driver does not cost the user their place); read when it starts, where flags on the command
// line win over what was saved.
#include "gi/scene/scene.h"

#include <filesystem>
#include <optional>
#include <string>

namespace lumina::app::viewer {

struct ViewerOptions;

struct ViewerSettings {
    std::string scene; // the scene argument the camera belongs to
    std::string technique;
    std::string preset;
    float exposureEv = 0.0f;
    bool vsync = true;
    std::string view; // a name of the view menu; empty: the final image
    std::optional<scene::Camera> camera;
};

// --settings PATH, else $XDG_CONFIG_HOME/lumina/viewer.json, else ~/.config/lumina/viewer.json;
// none for a scripted run (--frames, --screenshot-after or a test flag) without --settings, so
// tests neither read a user's settings nor leave theirs behind.
std::optional<std::filesystem::path> viewerSettingsPath(const ViewerOptions& options);

// The saved settings, or nothing when there is no file. A file that cannot be read, or a
// value that no longer exists (a preset renamed, say), is reported on stderr and skipped: a
// settings file never stops the viewer.
std::optional<ViewerSettings> loadViewerSettings(const std::filesystem::path& path);

// Puts saved settings into `options` where its flags left a choice: the technique, preset,
// exposure, vsync and view; the camera when `saved` is of the same scene.
void applySavedSettings(const ViewerSettings& saved, ViewerOptions& options);

// Writes `settings` (through a temporary file renamed over the old one, so a failure halfway
// leaves the old file whole), creating the folder. Throws std::runtime_error naming the path.
void saveViewerSettings(const std::filesystem::path& path, const ViewerSettings& settings);

} // namespace lumina::app::viewer
