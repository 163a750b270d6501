#pragma once
// The SH grid flags of `lumina render` (docs/sh_grid.md): probes, face size, bake budget,
// ringing window, and saving or loading a baked grid; each overriding the preset.
#include "app/cli.h"
#include "gi/sh_grid/sh_grid_settings.h"

#include <vector>

namespace lumina::app {

// `flags` followed by --sh-grid-probes, --sh-grid-face, --sh-grid-budget, --sh-grid-window,
// --sh-grid-save and --sh-grid-load.
std::vector<FlagSpec> withShGridFlags(std::vector<FlagSpec> flags);

// The preset's SH grid settings for `scene` with the flags applied; UsageError naming a bad value.
gi::ShGridSettings shGridSettings(const ParsedArgs& args, const gi::Preset& preset,
                                  const scene::Scene& scene);

} // namespace lumina::app
