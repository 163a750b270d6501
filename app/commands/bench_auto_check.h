#pragma once
// `lumina bench --check-auto E`: after the matrix, what `render --technique auto --error-budget E`
// would choose for each scene (its calibration: small, short, cached) against the cheapest
// configuration under E in the bench's own full matrix (docs/measurement.md).
#include "app/cli.h"
#include "gi/bench/bench_report.h"
#include "gi/core/pipeline_cache.h"
#include "gi/scene/scene.h"

#include <filesystem>
#include <vector>

namespace lumina::app {

// Prints one verdict per scene and writes `csv`; the real-time techniques and presets of the
// bench are the candidates. Returns how many scenes disagree.
size_t checkAutoChoices(rhi::IDevice& device, gi::PipelineCache& pipelines, const ParsedArgs& args,
                        const std::vector<scene::Scene>& scenes, const std::vector<std::string>& techniques,
                        const std::vector<std::string>& presets, const std::vector<gi::BenchRecord>& records,
                        const std::filesystem::path& csv);

} // namespace lumina::app
