#pragma once
// `--technique auto --error-budget E` for `lumina render` (and the bench's check of it): the
// calibration's flags, its table printed, and the choice (gi/bench/auto_technique.h).
#include "app/cli.h"
#include "gi/bench/auto_technique.h"

#include <optional>
#include <vector>

namespace lumina::app {

// --calibration-size, --calibration-frames, --calibration-spp (render and bench).
std::vector<FlagSpec> withCalibrationFlags(std::vector<FlagSpec> flags);
// Those and --error-budget, --auto-techniques, --auto-presets (render).
std::vector<FlagSpec> withAutoTechniqueFlags(std::vector<FlagSpec> flags);

// The calibration the flags ask for; UsageError for a bad value.
gi::CalibrationRequest calibrationRequest(const ParsedArgs& args);

// UsageError when a flag of --technique auto is given without it.
void requireAutoForAutoFlags(const ParsedArgs& args);

// --error-budget, required and positive; UsageError otherwise.
double errorBudget(const ParsedArgs& args);

// The table, each candidate marked against the budget, and what was chosen and why.
void printCalibration(const gi::Calibration& calibration, const gi::CalibrationRequest& request,
                      double budget, std::optional<size_t> choice);

// For `render --technique auto` and the viewer's: calibrates the scene (or reuses its table), prints the
// table and the choice, and returns the arguments with --technique and --preset set to it. Exit 1 (a
// runtime_error) when no candidate is under the budget.
ParsedArgs chooseAutoTechnique(const ParsedArgs& args);

} // namespace lumina::app
