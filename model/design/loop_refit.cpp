#include "model/design/loop_refit.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace nibrig::model::design {

forcing::ForcingExemplar print_exemplar(const std::string& name, const DesignPoint& point,
                                        const std::string& surface,
                                        const io::VelocitySpectrum& measured,
                                        std::vector<double> response,
                                        const forcing::ForcingModel& model) {
  validate(point);
  if (measured.speeds_m_s.size() != model.speeds_m_s.size())
    throw std::invalid_argument(
        fmt::format("{}: {} speeds measured, the forcing model has {} ({:g} to {:g} mm/s): capture "
                    "the print over a "
                    "profile that holds each of them (steps, 42 s)",
                    name, measured.speeds_m_s.size(), model.speeds_m_s.size(),
                    model.speeds_m_s.front() * 1e3, model.speeds_m_s.back() * 1e3));
  for (std::size_t s = 0; s < model.speeds_m_s.size(); ++s)
    if (std::abs(measured.speeds_m_s[s] - model.speeds_m_s[s]) > 1e-6)
      throw std::invalid_argument(
          fmt::format("{}: speed {} is {:g} mm/s, the forcing model's {:g} mm/s", name, s + 1,
                      measured.speeds_m_s[s] * 1e3, model.speeds_m_s[s] * 1e3));
  forcing::ForcingExemplar e;
  e.tool = name;
  e.surface = surface;
  e.material = point.mix.size() == 1 ? point.mix.front().material : "mix";
  for (const auto& share : point.mix) e.mix.emplace_back(share.material, share.fraction);
  e.tip_diameter_m = point.tip_diameter_m;
  e.tip_interpolated = true;
  try {
    e.measured = io::spectrum_at_frequencies(measured, model.frequencies_hz);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(name + ": " + error.what());
  }
  e.response_magnitude = std::move(response);
  return e;
}

forcing::ForcingModel refit_with_prints(std::span<const forcing::ForcingExemplar> catalog,
                                        std::span<const forcing::ForcingExemplar> prints,
                                        const forcing::ForcingModel& base) {
  std::vector<forcing::ForcingExemplar> all(catalog.begin(), catalog.end());
  all.insert(all.end(), prints.begin(), prints.end());
  forcing::ForcingFitOptions options;
  options.knot_frequencies_hz = base.knot_frequencies_hz;
  options.reference_tip_diameter_m = base.reference_tip_diameter_m;
  options.reference_material = base.reference_material;
  forcing::ForcingModel model = forcing::fit_forcing_model(all, options);
  for (const auto& [material, curve] : base.material_log_gain)
    model.material_log_gain.try_emplace(material, curve);
  for (const auto& [surface, forcing] : base.surface_forcing)
    model.surface_forcing.try_emplace(surface, forcing);
  model.material_log_gain_se = base.material_log_gain_se;
  model.surface_log_forcing_se = base.surface_log_forcing_se;
  model.held_out_descriptor_errors = base.held_out_descriptor_errors;
  model.descriptor_error_threshold = base.descriptor_error_threshold;
  model.notes = base.notes;
  model.notes.push_back(fmt::format(
      "refitted with {} design-loop print{} beside the catalog's {} exemplars, each print one "
      "exemplar of its mix and tip (model/design/loop_refit.hpp)",
      prints.size(), prints.size() == 1 ? "" : "s", catalog.size()));
  return model;
}

}  // namespace nibrig::model::design
