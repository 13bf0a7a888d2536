#include "ui/cli/forcing_calibration_json.hpp"

#include "model/forcing/forcing_model.hpp"

namespace nibrig::ui::cli {

namespace {

namespace forcing = model::forcing;
using nlohmann::json;

json repeatability_json(const std::optional<model::forcing::Repeatability>& r) {
  if (!r) return nullptr;
  return {{"rms_db", r->rms_db}, {"pairs", r->pairs.size()}};
}

json count_or_null(const std::optional<std::size_t>& n) { return n ? json(*n) : json(nullptr); }

std::vector<double> millimetres(std::span<const double> metres) {
  std::vector<double> out;
  for (double m : metres) out.push_back(m * 1e3);
  return out;
}

json fits_json(const std::vector<forcing::ExemplarFit>& fits) {
  json out = json::array();
  for (const auto& f : fits)
    out.push_back({{"tool", f.tool}, {"surface", f.surface}, {"rms_db", f.rms_db}});
  return out;
}

// What both material modes print of a calibration: its curve in dB per knot, with its SE.
json calibration_json(const forcing::MaterialCalibration& c) {
  json curve = json::array();
  for (std::size_t k = 0; k < c.model.knot_frequencies_hz.size(); ++k)
    curve.push_back(
        {{"frequency_hz", c.model.knot_frequencies_hz[k]},
         {"gain_db", forcing::log_gain_to_db(c.log_gain[k])},
         {"se_db", k < c.log_gain_se.size() ? json(forcing::log_gain_to_db(c.log_gain_se[k]))
                                            : json(nullptr)}});
  return {{"material", c.material},
          {"exemplars", c.exemplars},
          {"prints", c.prints},
          {"residual_rms_db", c.residual_rms_db},
          {"print_sd_db", forcing::log_gain_to_db(c.print_log_gain_sd)},
          {"degrees_of_freedom", c.degrees_of_freedom},
          {"curve", curve}};
}

json surface_count_study_json(const forcing::MaterialStudy& study) {
  json steps = json::array();
  for (const auto& s : study.steps)
    steps.push_back({{"surfaces", s.surfaces},
                     {"subsets", s.subsets},
                     {"exemplars", s.exemplars},
                     {"se_rms_db", s.se_rms_db},
                     {"exemplars_se_rms_db", s.within_se_rms_db},
                     {"prediction_rms_db", s.prediction_rms_db}});
  return {
      {"surfaces", study.surfaces}, {"predicted_prints", study.predicted_prints}, {"steps", steps}};
}

}  // namespace

json material_check_json(const forcing::MaterialCalibrationCheck& check,
                         const forcing::MaterialStudy* study, std::size_t mix_prints,
                         double seconds,
                         const std::optional<model::forcing::Repeatability>& repeatability) {
  json rows = json::array();
  for (const auto& p : check.prints)
    rows.push_back({{"tool", p.tool},
                    {"surface", p.surface},
                    {"tip_diameter_mm", p.tip_diameter_m * 1e3},
                    {"in_sample", p.calibration_print},
                    {"calibrated_rms_db", p.calibrated_rms_db},
                    {"uncalibrated_rms_db", p.uncalibrated_rms_db},
                    {"full_fit_rms_db", p.full_fit_rms_db},
                    {"full_fit_without_it_rms_db", p.full_loo_rms_db},
                    {"predicted_se_db", p.predicted_se_db}});
  json calibration = calibration_json(check.calibration);
  for (std::size_t k = 0; k < calibration["curve"].size(); ++k)
    calibration["curve"][k]["full_fit_gain_db"] =
        forcing::log_gain_to_db(check.full_fit_log_gain.at(k));
  json means = nullptr;
  if (check.predicted > 0)
    means = {{"prints", check.predicted},
             {"calibrated_db", check.mean_calibrated_db},
             {"uncalibrated_db", check.mean_uncalibrated_db},
             {"full_fit_db", check.mean_full_fit_db},
             {"full_fit_without_it_db", check.mean_full_loo_db}};
  return {{"command", "forcing calibrate-material"},
          {"mode", "check"},
          {"material", check.material},
          {"calibration_tips_mm", millimetres(check.calibration_tips_m)},
          {"seconds", seconds},
          {"repeatability", repeatability_json(repeatability)},
          {"print_errors", rows},
          {"means", means},
          {"mix_prints", mix_prints},
          {"calibration", calibration},
          {"surface_count_study", study ? surface_count_study_json(*study) : json(nullptr)}};
}

json material_calibration_json(const forcing::MaterialCalibration& c,
                               std::span<const double> calibration_tips_m,
                               const std::filesystem::path& forcing_model,
                               const std::vector<forcing::ExemplarFit>& predicted,
                               const std::optional<model::forcing::Repeatability>& repeatability) {
  return {{"command", "forcing calibrate-material"},
          {"mode", "against_model"},
          {"material", c.material},
          {"forcing_model", forcing_model.string()},
          {"calibration_tips_mm", millimetres(calibration_tips_m)},
          {"repeatability", repeatability_json(repeatability)},
          {"in_sample_prints", fits_json(c.print_fits)},
          {"predicted_prints", fits_json(predicted)},
          {"calibration", calibration_json(c)}};
}

json surface_study_json(const forcing::SurfaceStudy& study, const SurfaceStudyFindings& findings,
                        double seconds,
                        const std::optional<model::forcing::Repeatability>& repeatability) {
  json steps = json::array();
  for (const auto& s : study.steps)
    steps.push_back({{"tools", s.tools},
                     {"subsets", s.subsets},
                     // One tool has no spread to tell an SE by: the study's 0 is no value.
                     {"se_rms_db", s.tools >= 2 ? json(s.se_rms_db) : json(nullptr)},
                     {"prediction_rms_db", s.prediction_rms_db},
                     {"worst_subset_rms_db", s.worst_subset_rms_db}});
  const auto* table_step =
      findings.table_tools ? &study.steps.at(*findings.table_tools - 1) : nullptr;
  json tools = json::array();
  for (std::size_t i = 0; i < study.tools.size(); ++i)
    tools.push_back(
        {{"tool", study.tools[i]},
         {"predicted_rms_db", table_step ? json(table_step->tool_rms_db[i]) : json(nullptr)},
         {"full_fit_rms_db", study.full_fit_rms_db[i]},
         {"full_fit_without_it_rms_db", study.full_loo_rms_db[i]}});
  json written = nullptr;
  if (findings.written != nullptr)
    written = {{"tools", findings.written->tools},
               {"se_rms_db", findings.written->log_forcing_se.empty()
                                 ? json(nullptr)
                                 : json(findings.written->rms_se_db)}};
  return {{"command", "forcing calibrate-surface"},
          {"mode", "study"},
          {"surface", study.surface},
          {"seconds", seconds},
          {"repeatability", repeatability_json(repeatability)},
          {"steps", steps},
          {"mean_full_fit_db", study.mean_full_fit_db},
          {"mean_full_fit_without_it_db", study.mean_full_loo_db},
          {"fewest_tools_se_within_repeatability", count_or_null(findings.fewest_tools_se_within)},
          {"fewest_tools_predicted_within_repeatability",
           count_or_null(findings.fewest_tools_predicted_within)},
          {"tools_predicted_from", count_or_null(findings.table_tools)},
          {"tools", tools},
          {"written", written}};
}

json surface_calibration_json(const forcing::SurfaceCalibration& c,
                              const std::filesystem::path& forcing_model,
                              const std::optional<model::forcing::Repeatability>& repeatability) {
  json tools = json::array();
  for (const auto& t : c.tool_fits) tools.push_back({{"tool", t.tool}, {"rms_db", t.rms_db}});
  return {{"command", "forcing calibrate-surface"},
          {"mode", "against_model"},
          {"surface", c.surface},
          {"forcing_model", forcing_model.string()},
          {"repeatability", repeatability_json(repeatability)},
          {"residual_rms_db", c.residual_rms_db},
          // One tool gives the forcing but no SE: null, not the struct's 0.
          {"se_rms_db", c.log_forcing_se.empty() ? json(nullptr) : json(c.rms_se_db)},
          {"tools", tools}};
}

}  // namespace nibrig::ui::cli
