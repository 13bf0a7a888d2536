#include "model/design/material_hold_out.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "model/forcing/printed_tool_design.hpp"

namespace nibrig::model::design {

double equal_modulus_fraction(const mechanics::MaterialTable& materials,
                              const std::string& material, const std::string& first,
                              const std::string& second) {
  const auto modulus = [&](const std::string& m) {
    return materials.find(forcing::printed_tip_of(m, materials).material).youngs_modulus;
  };
  const double e = modulus(material), e_first = modulus(first), e_second = modulus(second);
  const auto mpa = [](double pa) {
    std::ostringstream out;
    out << std::setprecision(3) << pa * 1e-6 << " MPa";
    return out.str();
  };
  if (e_first == e_second || (e - e_first) * (e - e_second) > 0)
    throw std::invalid_argument("no mix of " + first + " and " + second + " (tip moduli " +
                                mpa(e_first) + " and " + mpa(e_second) + ") has the modulus of " +
                                material + " (" + mpa(e) + ")");
  return (e - e_first) / (e_second - e_first);
}

DesignPoint MaterialHoldOut::point_at(double tip_diameter_m) const {
  DesignPoint point;
  if (second_fraction < 1) point.mix.push_back({first, 1 - second_fraction});
  if (second_fraction > 0) point.mix.push_back({second, second_fraction});
  point.tip_diameter_m = tip_diameter_m;
  return point;
}

MaterialHoldOut hold_out_material(std::span<const forcing::ForcingExemplar> exemplars,
                                  const std::string& material, const std::string& first,
                                  const std::string& second, double second_fraction) {
  const std::string what = "holding out " + material + " as a mix of " + first + " and " + second;
  if (material == first || material == second || first == second)
    throw std::invalid_argument(what + ": three different materials are needed");
  if (!(second_fraction >= 0 && second_fraction <= 1))
    throw std::invalid_argument(what + ": the fraction of " + second + " must lie in [0, 1]");
  std::vector<forcing::ForcingExemplar> training;
  std::vector<const forcing::ForcingExemplar*> held_out;
  for (const auto& e : exemplars) {
    if (e.material == material)
      held_out.push_back(&e);
    else
      training.push_back(e);
  }
  if (held_out.empty()) throw std::invalid_argument(what + ": no exemplar is of " + material);
  if (const auto problems = forcing::fit_problems(training); !problems.empty()) {
    std::string text = what + ": the rest cannot be fitted:";
    for (const auto& p : problems) text += " " + p + ";";
    throw std::invalid_argument(text);
  }
  MaterialHoldOut out;
  out.model = forcing::fit_forcing_model(training);
  out.material = material;
  out.first = first;
  out.second = second;
  out.second_fraction = second_fraction;
  for (const forcing::ForcingExemplar* e : held_out) {
    const DesignPoint point = out.point_at(e->tip_diameter_m);
    const auto of_material_with_its_tip = [e](const std::string& m) -> NeighbourTest {
      return [e, m](const forcing::ForcingExemplar& x) {
        return x.material == m && forcing::same_tip(x.tip_diameter_m, e->tip_diameter_m);
      };
    };
    out.predictions.push_back(
        predict_held_out(out.model, *e, point, exemplars,
                         {of_material_with_its_tip(first), of_material_with_its_tip(second)}));
  }
  return out;
}

std::size_t MaterialResolution::effect_resolved_knots() const {
  return knots_beyond_two_errors(effect, effect_se);
}

std::size_t MaterialResolution::deviation_resolved_knots() const {
  return knots_beyond_two_errors(deviation, deviation_se);
}

MaterialResolution material_resolution(const forcing::CurveJackknife& jackknife,
                                       const std::string& material, const std::string& first,
                                       const std::string& second, double second_fraction) {
  for (const auto& m : {material, first, second})
    if (jackknife.full.material.count(m) == 0)
      throw std::invalid_argument("resolving " + material + " as a mix of " + first + " and " +
                                  second + ": the fit has no curve for " + m);
  MaterialResolution out;
  out.material = material;
  out.first = first;
  out.second = second;
  out.second_fraction = second_fraction;
  out.knot_frequencies_hz = jackknife.knot_frequencies_hz;
  out.tools = jackknife.replicates.size();
  using Curves = std::map<std::string, std::vector<double>>;
  const auto effect_at = [&](const Curves& m, std::size_t k) {
    return m.at(second)[k] - m.at(first)[k];
  };
  const auto offset_at = [&](const Curves& m, std::size_t k) {  // from the first material
    return m.at(material)[k] - m.at(first)[k];
  };
  const auto deviation_at = [&](const Curves& m, std::size_t k) {
    return offset_at(m, k) - second_fraction * effect_at(m, k);
  };
  // argmin_f Σ_k (offset_k − f·effect_k)²
  const auto fitted_fraction = [&](const Curves& m) {
    double cross = 0, squares = 0;
    for (std::size_t k = 0; k < out.knot_frequencies_hz.size(); ++k) {
      cross += offset_at(m, k) * effect_at(m, k);
      squares += effect_at(m, k) * effect_at(m, k);
    }
    return squares > 0 ? cross / squares : 0.0;
  };
  for (std::size_t k = 0; k < out.knot_frequencies_hz.size(); ++k) {
    out.effect.push_back(effect_at(jackknife.full.material, k));
    out.deviation.push_back(deviation_at(jackknife.full.material, k));
    out.effect_se.push_back(jackknife.standard_error(
        [&](const forcing::CurveReplicate& r) { return effect_at(r.material, k); }));
    out.deviation_se.push_back(jackknife.standard_error(
        [&](const forcing::CurveReplicate& r) { return deviation_at(r.material, k); }));
  }
  out.fitted_fraction = fitted_fraction(jackknife.full.material);
  out.fitted_fraction_se = jackknife.standard_error(
      [&](const forcing::CurveReplicate& r) { return fitted_fraction(r.material); });
  return out;
}

}  // namespace nibrig::model::design
