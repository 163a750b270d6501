#include "app/commands/ddgi_options.h"

#include "shaders/ddgi/ddgi_shared.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace lumina::app {

namespace {

// Most probes along an axis from the flags (a volume holds at most 65535 probes in all).
constexpr uint64_t kMaxProbesPerAxis = 256;

// "N" or "X,Y,Z".
glm::uvec3 parseCounts(const std::string& text) {
    std::vector<uint64_t> values;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, ',')) {
        if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos || part.size() > 4) {
            throw UsageError("--ddgi-probes: '" + text + "' is not N or X,Y,Z (whole numbers)");
        }
        values.push_back(std::stoull(part));
    }
    if (values.size() == 1) {
        values.assign(3, values[0]);
    }
    if (values.size() != 3 ||
        std::ranges::any_of(values, [](uint64_t v) { return v < 2 || v > kMaxProbesPerAxis; })) {
        throw UsageError("--ddgi-probes: '" + text + "' (expected N or X,Y,Z, each 2.." +
                         std::to_string(kMaxProbesPerAxis) + ")");
    }
    return {uint32_t(values[0]), uint32_t(values[1]), uint32_t(values[2])};
}

} // namespace

std::vector<FlagSpec> withDdgiFlags(std::vector<FlagSpec> flags) {
    flags.insert(
        flags.end(),
        {{"ddgi-probes", "N|X,Y,Z",
          "DDGI probes per axis of the fitted volume or of each cascade (overrides the preset: 8 low, 16 "
          "medium and high)"},
         {"ddgi-spacing", "S",
          "DDGI probe spacing in scene units: the fitted volume gets as many probes as fit (or the finest "
          "cascade this spacing)"},
         {"ddgi-rays", "N", "DDGI rays per probe and update, 33..256 (overrides the preset: 96, 144, 256)"},
         {"ddgi-hysteresis", "H", "share of DDGI probe history kept each update, 0..0.999 (default 0.97)"},
         {"ddgi-cascades", "N",
          "camera-centred DDGI cascades, 0..4 (0: one volume fitted to the scene; default: 3 for scenes "
          "over 200 m, else 0)"}});
    return flags;
}

gi::DdgiSettings ddgiSettings(const ParsedArgs& args, const gi::Preset& preset, const scene::Scene& scene) {
    gi::DdgiSettings s;
    try {
        s = gi::ddgiPreset(preset, scene);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    if (args.has("ddgi-probes")) {
        s.probeCounts = parseCounts(args.get("ddgi-probes"));
        s.volumes.clear();
    }
    if (args.has("ddgi-cascades")) {
        s.cascades = static_cast<uint32_t>(args.getUint("ddgi-cascades", 0, 0, LUMINA_DDGI_MAX_VOLUMES));
        s.volumes.clear();
    }
    // Cascades (the preset's or the flag's) reach across the scene with the probes they have.
    s.cascadeSpacing = s.cascades > 0 ? gi::ddgiCascadeSpacing(scene, s.cascades, s.probeCounts.x) : 0.0f;
    if (args.has("ddgi-spacing")) {
        const double spacing = args.getDouble("ddgi-spacing", 0.0);
        if (!(spacing > 0.0) || !std::isfinite(spacing)) {
            throw UsageError("--ddgi-spacing must be a positive length in scene units");
        }
        if (s.cascades > 0) {
            s.cascadeSpacing = float(spacing);
        } else {
            const glm::vec3 extent = scene.worldBounds().size();
            for (int axis = 0; axis < 3; ++axis) {
                s.probeCounts[axis] = uint32_t(
                    std::clamp<double>(std::ceil(extent[axis] / spacing), 2.0, double(kMaxProbesPerAxis)));
            }
            s.volumes.clear();
        }
    }
    // Beyond a few cascade cells the rays read the coarse global SDF (ddgiPreset's rule).
    s.nearFieldDistance = s.cascades > 0 ? gi::kDdgiCascadeNearFieldCells * s.cascadeSpacing : 0.0f;
    s.raysPerProbe = static_cast<uint32_t>(args.getUint("ddgi-rays", s.raysPerProbe, 0, UINT32_MAX));
    s.hysteresis = float(args.getDouble("ddgi-hysteresis", s.hysteresis));
    try {
        s.validate();
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    return s;
}

} // namespace lumina::app
