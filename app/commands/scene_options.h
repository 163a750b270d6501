#pragma once
// The flags of every command that loads a scene (render, info, reference, bench, sdf): the
// default light and the sky environment (gi/scene/scene_loader.h, LoadOptions), and the line
// that tells the user where the scene's light comes from.
#include "app/cli.h"
#include "gi/scene/scene_loader.h"

#include <string>
#include <vector>

namespace lumina::app {

// --no-default-light, --sky FILE.exr, --sky-intensity K.
std::vector<FlagSpec> sceneLoadFlags();

// `flags` followed by sceneLoadFlags().
std::vector<FlagSpec> withSceneLoadFlags(std::vector<FlagSpec> flags);

// The load options those flags ask for; UsageError for a bad intensity or an intensity
// without --sky.
scene::LoadOptions sceneLoadOptions(const ParsedArgs& args);

// Poses `scene` at the frame --animation-frame names, held still; false when the flag is absent.
// UsageError when the scene has no animation.
bool poseAtAnimationFrame(const ParsedArgs& args, scene::Scene& scene);

// "lights: ..." : what lights the scene and where it came from (the file, the default light,
// --sky), so a black or unexpectedly lit image is explained.
std::string lightingLine(const scene::Scene& scene);

} // namespace lumina::app
