#pragma once
// A scene's animation in words, one line per animated thing, for `lumina info` and logs:
// what is animated, by which tracks (their keys and interpolation), and the loop length.
#include "gi/scene/scene.h"

#include <string>
#include <vector>

namespace lumina::scene {

// The number of keyframe tracks: glTF channels plus the non-empty tracks of scripted paths.
size_t animationTrackCount(const SceneAnimation& animation);

// First line: the totals and loop length ("none" for a still scene); then one line per glTF
// animation and per scripted path, at most `maxLines` in all (the last says how many more).
std::vector<std::string> animationSummary(const Scene& scene, size_t maxLines = 24);

} // namespace lumina::scene
