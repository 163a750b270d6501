#include "app/commands/sh_grid_options.h"

#include <stdexcept>

namespace lumina::app {

std::vector<FlagSpec> withShGridFlags(std::vector<FlagSpec> flags) {
    flags.insert(
        flags.end(),
        {{"sh-grid-probes", "N",
          "SH grid probes along the scene's largest side, 2..64 (overrides the preset: 4 low, 6 "
          "medium, 8 high)"},
         {"sh-grid-face", "N", "SH grid cube-face size in texels, 8..512 (preset: 32, 64, 128)"},
         {"sh-grid-budget", "N", "SH grid probes baked per frame at most, 1..256 (preset: 8, 16, 32)"},
         {"sh-grid-window", "W",
          "Hann window over the SH bands against ringing, width W > 2 bands (default 0: off)"},
         {"sh-grid-save", "PATH", "write the baked SH grid to PATH after the last frame"},
         {"sh-grid-load", "PATH",
          "use the SH grid saved in PATH (same scene and grid settings) instead of baking"}});
    return flags;
}

gi::ShGridSettings shGridSettings(const ParsedArgs& args, const gi::Preset& preset,
                                  const scene::Scene& scene) {
    gi::ShGridSettings s = gi::shGridPreset(preset, scene);
    s.probesPerAxis = uint32_t(args.getUint("sh-grid-probes", s.probesPerAxis, 2, 64));
    s.faceSize = uint32_t(args.getUint("sh-grid-face", s.faceSize, 8, 512));
    s.probesPerFrame = uint32_t(args.getUint("sh-grid-budget", s.probesPerFrame, 1, 256));
    s.ringingWindow = float(args.getDouble("sh-grid-window", s.ringingWindow));
    s.loadPath = args.get("sh-grid-load");
    try {
        s.validate();
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    return s;
}

} // namespace lumina::app
