#include "model/forcing/forcing_model.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "model/forcing/hermite_curve.hpp"

namespace nibrig::model::forcing {

namespace {

template <typename Key>
std::string known_keys(const std::map<Key, std::vector<double>>& curves, double scale,
                       const std::string& unit) {
  std::ostringstream out;
  bool first = true;
  for (const auto& [key, curve] : curves) {
    out << (first ? "" : ", ");
    if constexpr (std::is_same_v<Key, double>)
      out << key * scale << unit;
    else
      out << key;
    first = false;
  }
  return out.str();
}

}  // namespace

double log_gain_to_db(double log_gain) { return 20.0 / std::numbers::ln10 * log_gain; }

bool same_tip(double a_m, double b_m) { return std::abs(a_m - b_m) < 1e-6; }

std::string tip_label(double diameter_m) {
  std::ostringstream out;
  out << diameter_m * 1e3 << " mm";
  return out.str();
}

const std::vector<double>& ForcingModel::tip_curve(double tip_diameter_m) const {
  for (const auto& [diameter, curve] : tip_log_gain)
    if (same_tip(diameter, tip_diameter_m)) return curve;
  std::ostringstream what;
  what << "forcing model has no tip curve for " << tip_diameter_m * 1e3
       << " mm (it has: " << known_keys(tip_log_gain, 1e3, " mm") << ")";
  throw std::invalid_argument(what.str());
}

const std::vector<double>& ForcingModel::material_curve(const std::string& material) const {
  const auto it = material_log_gain.find(material);
  if (it == material_log_gain.end())
    throw std::invalid_argument("forcing model has no material curve for '" + material +
                                "' (it has: " + known_keys(material_log_gain, 1.0, "") + ")");
  return it->second;
}

double ForcingModel::tip_log_gain_at(double tip_diameter_m, double frequency_hz) const {
  return hermite_value(knot_frequencies_hz, tip_curve(tip_diameter_m), frequency_hz);
}

double ForcingModel::material_log_gain_at(const std::string& material, double frequency_hz) const {
  return hermite_value(knot_frequencies_hz, material_curve(material), frequency_hz);
}

double ForcingModel::material_log_gain_se_at(const std::string& material,
                                             double frequency_hz) const {
  const auto it = material_log_gain_se.find(material);
  if (it == material_log_gain_se.end()) return 0.0;
  double se = 0.0;
  for (const auto& [k, w] : hermite_weights(knot_frequencies_hz, frequency_hz))
    se += std::abs(w) * it->second.at(k);
  return se;
}

double ForcingModel::surface_log_forcing_se_at(const std::string& surface, std::size_t speed,
                                               std::size_t frequency) const {
  const auto it = surface_log_forcing_se.find(surface);
  return it == surface_log_forcing_se.end() ? 0.0 : it->second.at(speed).at(frequency);
}

double ForcingModel::prediction_log_se(const std::string& surface, const std::string& material,
                                       std::size_t speed, std::size_t frequency) const {
  return std::hypot(material_log_gain_se_at(material, frequencies_hz.at(frequency)),
                    surface_log_forcing_se_at(surface, speed, frequency));
}

io::VelocitySpectrum ForcingModel::predict(std::span<const double> response_magnitude,
                                           const std::string& surface, double tip_diameter_m,
                                           const std::string& material) const {
  const auto forcing = surface_forcing.find(surface);
  if (forcing == surface_forcing.end()) {
    std::string known;
    for (const auto& [id, f] : surface_forcing) known += (known.empty() ? "" : ", ") + id;
    throw std::invalid_argument("forcing model has no surface '" + surface + "' (it has: " + known +
                                ")");
  }
  if (response_magnitude.size() != frequencies_hz.size())
    throw std::invalid_argument(
        "forcing model prediction: " + std::to_string(response_magnitude.size()) +
        " response values for " + std::to_string(frequencies_hz.size()) + " model frequencies");
  const auto& tip = tip_curve(tip_diameter_m);
  const auto& mat = material_curve(material);
  io::VelocitySpectrum out{frequencies_hz, speeds_m_s, {}};
  std::vector<double> gain(frequencies_hz.size());
  for (std::size_t j = 0; j < gain.size(); ++j) {
    const double h = response_magnitude[j];
    if (!(std::isfinite(h) && h >= 0))
      throw std::invalid_argument("forcing model prediction: |H| at " +
                                  std::to_string(frequencies_hz[j]) +
                                  " Hz is negative or not finite");
    gain[j] = h * std::exp(hermite_value(knot_frequencies_hz, tip, frequencies_hz[j]) +
                           hermite_value(knot_frequencies_hz, mat, frequencies_hz[j]));
  }
  for (const auto& row : forcing->second) {
    std::vector<double> amplitude(row.size());
    for (std::size_t j = 0; j < row.size(); ++j) amplitude[j] = row[j] * gain[j];
    out.amplitude_m_s2.push_back(std::move(amplitude));
  }
  return out;
}

}  // namespace nibrig::model::forcing
