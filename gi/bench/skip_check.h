#pragma once
// `lumina bench --verify-skips` (docs/measurement.md#skips): every skip of work whose output would
// not change (a shadow map of geometry that did not move, radiosity that converged, an SH grid
// with nothing owed; FrameContext::mayReuse) is checked by running the same configuration again
// with that skip forced off: what the skip saves per frame, and how far the image moves without
// it, which must stay within kSkipImageTolerance. Skips that leave nothing to run (no light of
// that kind, a strategy that draws no rays, no volume to reset) cannot be forced and are listed
// as such.
#include "gi/bench/reference_cache.h"
#include "gi/bench/technique_runs.h"
#include "gi/core/pipeline_cache.h"
#include "gi/frame/gi_technique.h"
#include "gi/scene/scene.h"
#include "rhi/device.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::gi {

// Largest relMSE of the final image with a skip forced off against the image with it: a skip
// that changes more than this changes the image, and the check fails.
inline constexpr double kSkipImageTolerance = 1e-3;

struct SkipCheck {
    std::string scene;
    std::string technique;
    std::string preset;
    std::string pass;                 // the pass forced (it stands for its group's passes)
    std::string reason;               // why the baseline skipped it, in the most frames
    uint32_t framesSkipped = 0;       // in the baseline
    bool forceable = false;           // false: nothing to run; the fields below are then empty
    uint32_t framesSkippedForced = 0; // the group's skips left in the forced run (0: forcing took)
    double frameMs = 0.0;             // the baseline's median frame after it settled (else all frames)
    double forcedFrameMs = 0.0;       // the forced run's median over the same frames
    double imageRelMse = 0.0;         // forced run's final image against the baseline's
    double savedMs() const { return forcedFrameMs - frameMs; }
    bool withinTolerance() const { return !forceable || imageRelMse <= kSkipImageTolerance; }
};

// The pass whose forcing covers `pass`'s skips ("surface cache: radiosity filter" is forced with
// "surface cache: radiosity trace"), or empty when `pass`'s skips cannot be forced.
std::string forcedPassFor(std::string_view pass);

// One check per group of skipped passes in `baseline` (a run of `technique` at `preset` with
// `request`): the forceable ones run again with the skip forced off.
std::vector<SkipCheck> checkSkips(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                                  GiTechnique technique, const std::string& preset, const RunRequest& request,
                                  const Reference& reference, const TechniqueRun& baseline);

void writeSkipChecksCsv(const std::filesystem::path& path, const std::vector<SkipCheck>& checks);

} // namespace lumina::gi
