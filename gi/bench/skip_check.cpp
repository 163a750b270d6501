#include "gi/bench/skip_check.h"

#include "gi/deferred/point_shadow_pass.h"
#include "gi/deferred/sun_shadow_pass.h"
#include "gi/measure/metrics.h"
#include "gi/sdf/scene_sdf.h"
#include "gi/sh_grid/sh_grid_gi.h"
#include "gi/surface_cache/radiosity_pass.h"
#include "gi/surface_cache/surface_cache.h"
#include "gi/surface_cache/surface_cache_combine_pass.h"
#include "gi/surface_cache/surface_cache_direct_light_pass.h"
#include "gi/surface_cache/voxel_lighting_pass.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <stdexcept>

namespace lumina::gi {

namespace {

// Passes skipped together and forced together: the first is the one FrameContext::mayReuse is
// asked about (surface_cache.cpp forces combine and voxel lighting as one, radiosity's three
// passes as one update).
const std::vector<std::vector<std::string>>& forceableGroups() {
    static const std::vector<std::vector<std::string>> groups = {
        {SunShadowPass::kPassName},
        {PointShadowPass::kPassName, std::string(PointShadowPass::kPassName) + ": unchanged cubes"},
        {surface_cache::SurfaceCacheDirectLightPass::kPassName},
        {surface_cache::SurfaceCacheCombinePass::kPassName, surface_cache::VoxelLightingPass::kInjectPassName,
         surface_cache::VoxelLightingPass::kResolvePassName},
        {surface_cache::RadiosityPass::kTracePassName, surface_cache::RadiosityPass::kFilterPassName,
         surface_cache::RadiosityPass::kIntegratePassName},
        {ShGridGi::kBakeName},
        {sdf::SceneSdf::kComposePassName},
        {surface_cache::SurfaceCache::kCapturePassName},
    };
    return groups;
}

// A skip that left nothing to render (no light of that kind, no cards): forcing changes nothing.
bool nothingToRun(const SkipCount& skip) {
    return skip.kind != SkipKind::Reuse;
}

// Median GPU ms of `run`'s frames from `first` (0-based) on. Both runs of a check are measured
// over the same frames, those after the baseline settled: the forced run may settle later or never,
// and its whole run's median against the baseline's settled one made savings come out negative.
double medianFrom(const TechniqueRun& run, uint32_t first) {
    const size_t start = std::min<size_t>(first, run.frameMsEach.size());
    std::vector<double> frames(run.frameMsEach.begin() + std::ptrdiff_t(start), run.frameMsEach.end());
    return frames.empty() ? run.frameMs : median(std::move(frames));
}

} // namespace

std::string forcedPassFor(std::string_view pass) {
    for (const std::vector<std::string>& group : forceableGroups()) {
        if (std::ranges::find(group, pass) != group.end()) {
            return group.front();
        }
    }
    return {};
}

std::vector<SkipCheck> checkSkips(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                                  GiTechnique technique, const std::string& preset, const RunRequest& request,
                                  const Reference& reference, const TechniqueRun& baseline) {
    // Per group (its forced pass, else the pass itself): frames skipped and the commonest reason.
    struct Group {
        uint32_t frames = 0;
        std::string reason;
        uint32_t reasonFrames = 0;
        bool structural = true;
    };
    std::map<std::string, Group> groups;
    for (const SkipCount& skip : baseline.skips) {
        const std::string forced = forcedPassFor(skip.pass);
        Group& group = groups[forced.empty() ? skip.pass : forced];
        group.frames = std::max(group.frames, skip.frames);
        if (skip.frames > group.reasonFrames) {
            group.reason = skip.reason;
            group.reasonFrames = skip.frames;
        }
        group.structural = group.structural && (forced.empty() || nothingToRun(skip));
    }
    std::vector<SkipCheck> checks;
    for (const auto& [pass, group] : groups) {
        SkipCheck check{.scene = scene.name,
                        .technique = baseline.technique,
                        .preset = preset,
                        .pass = pass,
                        .reason = group.reason,
                        .framesSkipped = group.frames,
                        .forceable = !group.structural};
        if (check.forceable) {
            RunRequest forcedRequest = request;
            forcedRequest.forcedPasses = {pass};
            const TechniqueRun forced =
                runRealTime(device, pipelines, scene, technique, preset, forcedRequest, reference);
            for (const SkipCount& skip : forced.skips) {
                if (forcedPassFor(skip.pass) == pass && !nothingToRun(skip)) {
                    check.framesSkippedForced = std::max(check.framesSkippedForced, skip.frames);
                }
            }
            const uint32_t first = baseline.settledAfterFrame.value_or(0);
            check.frameMs = medianFrom(baseline, first);
            check.forcedFrameMs = medianFrom(forced, first);
            check.imageRelMse = measure::relMse(baseline.finalImage, forced.finalImage);
        }
        checks.push_back(std::move(check));
    }
    return checks;
}

void writeSkipChecksCsv(const std::filesystem::path& path, const std::vector<SkipCheck>& checks) {
    std::ofstream out(path);
    out << "scene,technique,preset,pass,reason,frames_skipped,forceable,frames_skipped_forced,frame_ms,"
           "forced_frame_ms,saved_ms,image_relmse,tolerance,within\n";
    for (const SkipCheck& c : checks) {
        std::string reason = c.reason;
        std::ranges::replace(reason, ',', ';');
        std::ranges::replace(reason, '"', '\'');
        out << c.scene << ',' << c.technique << ',' << c.preset << ',' << c.pass << ",\"" << reason << "\","
            << c.framesSkipped << ',' << (c.forceable ? 1 : 0) << ',';
        if (c.forceable) {
            out << c.framesSkippedForced << ',' << c.frameMs << ',' << c.forcedFrameMs << ',' << c.savedMs()
                << ',' << c.imageRelMse;
        } else {
            out << ",,,,";
        }
        out << ',' << kSkipImageTolerance << ',' << (c.withinTolerance() ? 1 : 0) << '\n';
    }
    if (!out) {
        throw std::runtime_error("cannot write '" + path.string() + "'");
    }
}

} // namespace lumina::gi
