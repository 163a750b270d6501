#pragma once
// The DDGI flags of `lumina render` (docs/ddgi.md): probe counts, spacing, rays, hysteresis,
// cascades, each overriding the preset (and a scene file's "ddgiVolumes").
#include "app/cli.h"
#include "gi/ddgi/ddgi_settings.h"

#include <vector>

namespace lumina::app {

// `flags` followed by --ddgi-probes, --ddgi-spacing, --ddgi-rays, --ddgi-hysteresis, --ddgi-cascades.
std::vector<FlagSpec> withDdgiFlags(std::vector<FlagSpec> flags);

// The preset's DDGI settings for `scene` with the flags applied; UsageError naming a bad value.
gi::DdgiSettings ddgiSettings(const ParsedArgs& args, const gi::Preset& preset, const scene::Scene& scene);

} // namespace lumina::app
