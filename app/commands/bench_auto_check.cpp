#include "app/commands/bench_auto_check.h"

#include "app/commands/auto_technique_option.h"
#include "gi/bench/auto_technique.h"
#include "gi/bench/reference_cache.h"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace lumina::app {

size_t checkAutoChoices(rhi::IDevice& device, gi::PipelineCache& pipelines, const ParsedArgs& args,
                        const std::vector<scene::Scene>& scenes, const std::vector<std::string>& techniques,
                        const std::vector<std::string>& presets, const std::vector<gi::BenchRecord>& records,
                        const std::filesystem::path& csv) {
    const double budget = args.getDouble("check-auto", 0.0);
    gi::CalibrationRequest request = calibrationRequest(args);
    request.techniques = techniques;
    request.presets = presets;
    std::ofstream out(csv);
    if (!out) {
        throw std::runtime_error("cannot write '" + csv.string() + "'");
    }
    out << std::setprecision(9)
        << "scene,error_budget,auto_technique,auto_preset,auto_calibration_relmse,auto_calibration_ms,"
           "auto_matrix_relmse,auto_matrix_ms,matrix_technique,matrix_preset,matrix_relmse,matrix_ms,"
           "agrees\n";
    size_t disagreements = 0;
    for (const scene::Scene& scene : scenes) {
        // The bench's rows of this scene as candidates, measured at its full size and length.
        std::vector<gi::AutoCandidate> matrix;
        for (const gi::BenchRecord& record : records) {
            if (record.scene == scene.name && record.run.technique != "pathtracer") {
                matrix.push_back({record.run.technique, record.run.preset, record.run.frameMs,
                                  record.run.checkpoints.back().relMse});
            }
        }
        const gi::Calibration calibration =
            gi::loadOrCalibrate(device, pipelines, scene, request, gi::defaultCalibrationDirectory(),
                                gi::defaultReferenceDirectory());
        const std::optional<size_t> autoChoice = gi::cheapestUnder(calibration.candidates, budget);
        const std::optional<size_t> matrixChoice = gi::cheapestUnder(matrix, budget);
        const auto name = [](const std::vector<gi::AutoCandidate>& table, std::optional<size_t> i) {
            return i ? table[*i].technique + " " + table[*i].preset : std::string("none");
        };
        const bool agrees = name(calibration.candidates, autoChoice) == name(matrix, matrixChoice);
        disagreements += agrees ? 0 : 1;
        std::cout << "  auto check " << scene.name << ", relMSE <= " << budget << ": auto (calibrated at "
                  << request.width << "x" << request.height << ", " << request.frames << " frames) chooses "
                  << name(calibration.candidates, autoChoice)
                  << ", the matrix's cheapest under the budget is " << name(matrix, matrixChoice) << ": "
                  << (agrees ? "agrees" : "differs") << '\n';
        // Auto's choice as the matrix measured it: what the choice really costs and errs at full size.
        std::optional<size_t> autoInMatrix;
        for (size_t i = 0; autoChoice && i < matrix.size(); ++i) {
            if (matrix[i].technique == calibration.candidates[*autoChoice].technique &&
                matrix[i].preset == calibration.candidates[*autoChoice].preset) {
                autoInMatrix = i;
            }
        }
        const auto field = [](std::optional<double> v) {
            std::ostringstream text;
            text << std::setprecision(9);
            if (v) {
                text << *v;
            }
            return text.str();
        };
        const auto at = [](const std::vector<gi::AutoCandidate>& t, std::optional<size_t> i,
                           double gi::AutoCandidate::*member) {
            return i ? std::optional<double>(t[*i].*member) : std::nullopt;
        };
        out << scene.name << ',' << budget << ','
            << (autoChoice ? calibration.candidates[*autoChoice].technique + ',' +
                                 calibration.candidates[*autoChoice].preset
                           : std::string(","))
            << ',' << field(at(calibration.candidates, autoChoice, &gi::AutoCandidate::relMse)) << ','
            << field(at(calibration.candidates, autoChoice, &gi::AutoCandidate::frameMs)) << ','
            << field(at(matrix, autoInMatrix, &gi::AutoCandidate::relMse)) << ','
            << field(at(matrix, autoInMatrix, &gi::AutoCandidate::frameMs)) << ','
            << (matrixChoice ? matrix[*matrixChoice].technique + ',' + matrix[*matrixChoice].preset
                             : std::string(","))
            << ',' << field(at(matrix, matrixChoice, &gi::AutoCandidate::relMse)) << ','
            << field(at(matrix, matrixChoice, &gi::AutoCandidate::frameMs)) << ',' << (agrees ? 1 : 0)
            << '\n';
    }
    return disagreements;
}

} // namespace lumina::app
