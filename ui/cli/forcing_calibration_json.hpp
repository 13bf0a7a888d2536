// What `forcing calibrate-material|calibrate-surface` print, as JSON for `--json FILE`: one object
// per mode (the check or the study on the catalog, a calibration against a model), built from the
// structs the printed tables show, so a script or a test reads the numbers rather than the prose.
// Frequencies in Hz, tips in mm, errors in dB; a value that does not apply is null, never 0.
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <vector>

#include "model/forcing/material_calibration_check.hpp"
#include "model/forcing/material_calibration_study.hpp"
#include "model/forcing/measurement_repeatability.hpp"
#include "model/forcing/surface_calibration.hpp"
#include "model/forcing/surface_calibration_study.hpp"

namespace nibrig::ui::cli {

// The check on the catalog: `study` null when no print was left to predict (it was not run).
nlohmann::json material_check_json(
    const model::forcing::MaterialCalibrationCheck& check,
    const model::forcing::MaterialStudy* study, std::size_t mix_prints, double seconds,
    const std::optional<model::forcing::Repeatability>& repeatability);

// A calibration against the model in `forcing_model`; `predicted`: its other prints.
nlohmann::json material_calibration_json(
    const model::forcing::MaterialCalibration& c, std::span<const double> calibration_tips_m,
    const std::filesystem::path& forcing_model,
    const std::vector<model::forcing::ExemplarFit>& predicted,
    const std::optional<model::forcing::Repeatability>& repeatability);

// What the command concluded from a surface study: the fewest tools within the repeatability
// (none without one), the per-tool table's k (none when not shown), the calibration written.
struct SurfaceStudyFindings {
  std::optional<std::size_t> fewest_tools_se_within, fewest_tools_predicted_within;
  std::optional<std::size_t> table_tools;
  const model::forcing::SurfaceCalibration* written = nullptr;
};

nlohmann::json surface_study_json(
    const model::forcing::SurfaceStudy& study, const SurfaceStudyFindings& findings, double seconds,
    const std::optional<model::forcing::Repeatability>& repeatability);

nlohmann::json surface_calibration_json(
    const model::forcing::SurfaceCalibration& c, const std::filesystem::path& forcing_model,
    const std::optional<model::forcing::Repeatability>& repeatability);

}  // namespace nibrig::ui::cli
