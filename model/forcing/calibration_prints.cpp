#include "model/forcing/calibration_prints.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "model/forcing/leave_one_out.hpp"

namespace nibrig::model::forcing {

std::string print_name(const ForcingExemplar& print) { return print.tool + " on " + print.surface; }

void check_print_grid(const ForcingModel& model, const ForcingExemplar& print,
                      const std::string& what) {
  const std::string name = what + ": " + print_name(print);
  const auto& m = print.measured;
  if (m.frequencies_hz != model.frequencies_hz || m.speeds_m_s != model.speeds_m_s)
    throw std::invalid_argument(name +
                                ": its spectrum's frequencies or speeds differ from the "
                                "forcing model's (" +
                                std::to_string(model.frequencies_hz.size()) + " frequencies, " +
                                std::to_string(model.speeds_m_s.size()) + " speeds)");
  if (m.amplitude_m_s2.size() != m.speeds_m_s.size())
    throw std::invalid_argument(name + ": one amplitude row per speed expected");
  for (const auto& row : m.amplitude_m_s2)
    if (row.size() != m.frequencies_hz.size())
      throw std::invalid_argument(name + ": one amplitude per frequency expected in every row");
  if (print.response_magnitude.size() != m.frequencies_hz.size())
    throw std::invalid_argument(name + ": its response has " +
                                std::to_string(print.response_magnitude.size()) + " values for " +
                                std::to_string(m.frequencies_hz.size()) + " frequencies");
  for (double h : print.response_magnitude)
    if (!(std::isfinite(h) && h > 0))
      throw std::invalid_argument(name + ": its response magnitude must be finite and > 0");
}

LogCells print_log_data(const ForcingExemplar& print) {
  LogCells y;
  for (const auto& row : print.measured.amplitude_m_s2) {
    y.emplace_back();
    for (std::size_t j = 0; j < row.size(); ++j)
      y.back().push_back(row[j] > 0 && std::isfinite(row[j])
                             ? std::log(row[j]) - std::log(print.response_magnitude[j])
                             : std::numeric_limits<double>::quiet_NaN());
  }
  return y;
}

CalibrationResiduals residual_summary(std::span<const ForcingExemplar> prints,
                                      const std::vector<LogCells>& residuals) {
  CalibrationResiduals out;
  double total = 0.0;
  std::size_t total_count = 0;
  for (std::size_t g = 0; g < prints.size(); ++g) {
    double sum = 0.0;
    std::size_t count = 0;
    for (const auto& row : residuals[g])
      for (double r : row)
        if (std::isfinite(r)) {
          sum += r * r;
          ++count;
        }
    total += sum;
    total_count += count;
    out.per_print.push_back(
        {prints[g].tool, prints[g].surface,
         log_gain_to_db(std::sqrt(sum / static_cast<double>(std::max<std::size_t>(count, 1))))});
  }
  out.rms_db =
      log_gain_to_db(std::sqrt(total / static_cast<double>(std::max<std::size_t>(total_count, 1))));
  return out;
}

std::vector<ForcingExemplar> prints_of_material(std::span<const ForcingExemplar> exemplars,
                                                const std::string& material,
                                                std::span<const double> tips_m) {
  std::vector<ForcingExemplar> out;
  for (const auto& e : exemplars)
    if (e.material == material &&
        (tips_m.empty() || std::any_of(tips_m.begin(), tips_m.end(),
                                       [&](double t) { return same_tip(t, e.tip_diameter_m); })))
      out.push_back(e);
  if (std::none_of(exemplars.begin(), exemplars.end(),
                   [&](const auto& e) { return e.material == material; }))
    throw std::invalid_argument("no printed tool of material '" + material + "' was measured");
  for (double t : tips_m)
    if (std::none_of(out.begin(), out.end(),
                     [&](const auto& e) { return same_tip(t, e.tip_diameter_m); }))
      throw std::invalid_argument("no print of material '" + material + "' has a " + tip_label(t) +
                                  " tip");
  return out;
}

std::vector<ForcingExemplar> tools_on_surface(std::span<const ForcingExemplar> exemplars,
                                              const std::string& surface,
                                              std::span<const std::string> tools) {
  std::vector<ForcingExemplar> out;
  for (const auto& e : exemplars)
    if (e.surface == surface &&
        (tools.empty() || std::find(tools.begin(), tools.end(), e.tool) != tools.end()))
      out.push_back(e);
  if (std::none_of(exemplars.begin(), exemplars.end(),
                   [&](const auto& e) { return e.surface == surface; }))
    throw std::invalid_argument("no printed tool was measured on surface '" + surface + "'");
  for (const auto& t : tools)
    if (std::none_of(out.begin(), out.end(), [&](const auto& e) { return e.tool == t; }))
      throw std::invalid_argument("tool '" + t + "' was not measured on surface '" + surface +
                                  "' (or is not a printed tool with a design)");
  return out;
}

std::vector<ExemplarFit> prediction_errors(const ForcingModel& model,
                                           std::span<const ForcingExemplar> exemplars) {
  std::vector<ExemplarFit> out;
  for (const auto& e : exemplars)
    out.push_back({e.tool, e.surface,
                   log_spectrum_error(
                       model.predict(e.response_magnitude, e.surface, e.tip_diameter_m, e.material),
                       e.measured)
                       .rms_db});
  return out;
}

std::vector<ExemplarFit> unused_print_errors(const ForcingModel& model, std::span<const ForcingExemplar> exemplars,
                                             const std::string& material, std::span<const ForcingExemplar> used) {
  std::vector<ForcingExemplar> others;
  for (const auto& e : exemplars)
    if (e.material == material && model.surface_forcing.count(e.surface) &&
        std::none_of(used.begin(), used.end(),
                     [&](const auto& p) { return p.tool == e.tool && p.surface == e.surface; }))
      others.push_back(e);
  return prediction_errors(model, others);
}

}  // namespace nibrig::model::forcing
