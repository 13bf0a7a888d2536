#include "model/design/predicted_tool.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "model/design/calibration_uncertainty.hpp"
#include "model/design/mixed_design.hpp"
#include "model/design/tip_bracket.hpp"
#include "model/forcing/printed_tool_design.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/modal/frequency_response.hpp"
#include "model/space/catalog_descriptors.hpp"

namespace nibrig::model::design {

std::vector<double> interpolated_log_gain(const forcing::ForcingModel& model,
                                          const DesignPoint& point,
                                          std::span<const double> frequencies_hz) {
  validate(point);
  const std::vector<double> tips = fitted_tips(model);
  const TipBracket b = bracket_tip(tips, point.tip_diameter_m, "the forcing model's tip curves");
  std::vector<double> gain(frequencies_hz.size(), 0.0);
  for (std::size_t j = 0; j < frequencies_hz.size(); ++j) {
    const double f = frequencies_hz[j];
    gain[j] = (1 - b.weight) * model.tip_log_gain_at(tips[b.lower], f) +
              b.weight * model.tip_log_gain_at(tips[b.upper], f);
    for (const auto& share : point.mix)
      gain[j] += share.fraction * model.material_log_gain_at(share.material, f);
  }
  return gain;
}

io::VelocitySpectrum predict_spectrum(const forcing::ForcingModel& model, const DesignPoint& point,
                                      const std::string& surface,
                                      std::span<const double> response_magnitude) {
  // The reference tool's prediction carries |H|·F_S (and every check of the inputs); the
  // interpolated scalings multiply it.
  io::VelocitySpectrum spectrum = model.predict(
      response_magnitude, surface, model.reference_tip_diameter_m, model.reference_material);
  const std::vector<double> gain = interpolated_log_gain(model, point, model.frequencies_hz);
  for (auto& row : spectrum.amplitude_m_s2)
    for (std::size_t j = 0; j < row.size(); ++j) row[j] *= std::exp(gain[j]);
  return spectrum;
}

FrictionPrediction interpolated_friction(const io::Catalog& catalog, const DesignPoint& point,
                                         const std::string& surface) {
  validate(point);
  FrictionPrediction friction;
  friction.measured = point.mix.size() == 1;
  for (const auto& share : point.mix) {
    std::map<double, double> by_tip;  // diameter → μ of the printed tools of this material
    for (const auto& pairing : catalog.pairings) {
      if (pairing.surface != surface || !pairing.friction) continue;
      const auto tool = std::find_if(catalog.tools.begin(), catalog.tools.end(),
                                     [&](const auto& t) { return t.id == pairing.tool; });
      if (tool == catalog.tools.end() || tool->kind != "printed" ||
          tool->material != share.material || !tool->tip_diameter_m ||
          tool->id.find("_nail") != std::string::npos)
        continue;
      by_tip[*tool->tip_diameter_m] = pairing.friction->mu;
    }
    const std::string what = "friction of printed " + share.material + " tools on " + surface;
    if (by_tip.empty()) throw std::invalid_argument(what + ": the catalog has none measured");
    std::vector<double> tips, mus;
    for (const auto& [d, m] : by_tip) {
      tips.push_back(d);
      mus.push_back(m);
    }
    const TipBracket b = bracket_tip(tips, point.tip_diameter_m, what);
    friction.mu += share.fraction * ((1 - b.weight) * mus[b.lower] + b.weight * mus[b.upper]);
    if (b.lower != b.upper) friction.measured = false;
  }
  return friction;
}

namespace {

void require_setup(const PredictionSetup& setup) {
  if (setup.model == nullptr || setup.catalog == nullptr || setup.threshold == nullptr)
    throw std::invalid_argument("predict_tool: the setup needs a model, a catalog and a threshold");
}

// The cheap checks (a tip out of range, an unknown surface, no friction) and μ: run before the FEM
// so that a bad request fails in milliseconds, not after a second of meshing.
FrictionPrediction checked_friction(const PredictionSetup& setup, const DesignPoint& point,
                                    const std::string& surface) {
  require_setup(setup);
  const forcing::ForcingModel& model = *setup.model;
  interpolated_log_gain(model, point, model.frequencies_hz);
  if (model.surface_forcing.count(surface) == 0) {
    std::string known;
    for (const auto& [id, forcing] : model.surface_forcing)
      known += (known.empty() ? "" : ", ") + id;
    throw std::invalid_argument("the forcing model has no surface '" + surface + "' (it has " +
                                known + ")");
  }
  return interpolated_friction(*setup.catalog, point, surface);
}

PredictedTool assemble(const PredictionSetup& setup, const DesignPoint& point,
                       const std::string& surface, const FrictionPrediction& friction,
                       SimulatedResponse response) {
  PredictedTool tool;
  tool.point = point;
  tool.surface = surface;
  tool.mu = friction.mu;
  if (setup.descriptor_errors != nullptr)
    tool.descriptor_errors =
        friction.measured ? setup.descriptor_errors->without_friction() : *setup.descriptor_errors;
  tool.design_name = std::move(response.design_name);
  if (response.modal.size() == 0)
    throw std::invalid_argument("predict_tool: the response of '" + tool.design_name +
                                "' has no modes");
  tool.first_mode_hz = response.modal.omega.front() / (2 * M_PI);
  tool.modal = std::move(response.modal);
  tool.response_magnitude = std::move(response.response_magnitude);
  tool.spectrum = predict_spectrum(*setup.model, point, surface, tool.response_magnitude);
  tool.vibration = measure::compute_vibration_descriptors(tool.spectrum, *setup.threshold);
  // A material or surface calibrated from a few prints moves the descriptors by its own error,
  // beside the cross-validated one, and so does a lab material's ring-down calibration of its
  // modulus and damping for a stylus printed whole of it (calibration_uncertainty.hpp).
  auto& errors = tool.descriptor_errors;
  const auto with_errors = [&]() -> DescriptorErrorCovariance& {
    if (errors.empty()) {
      errors.names = space::all_paper_descriptor_names();
      const auto n = static_cast<Eigen::Index>(errors.names.size());
      errors.covariance = Eigen::MatrixXd::Zero(n, n);
    }
    return errors;
  };
  if (has_calibration_errors(*setup.model, point, surface))
    with_errors().covariance += calibration_descriptor_covariance(
        *setup.model, point, surface, tool.spectrum, *setup.threshold, with_errors().names);
  if (point.mix.size() == 1) {
    const forcing::PrintedTip tip =
        forcing::printed_tip_of(point.mix.front().material, setup.materials);
    const mechanics::Material& material = setup.materials.find(tip.material);
    if (tip.whole_tool && (material.youngs_modulus_sd || material.rayleigh_stiffness_sd)) {
      const auto damping = mixed_design(point, setup.template_design, setup.materials)
                               .design.damping.value_or(mechanics::RayleighDamping{});
      with_errors().covariance += material_constants_covariance(
          tool.modal, damping, material, tool.spectrum, *setup.threshold, with_errors().names);
    }
  }
  // The template's body and each material of the mix as printed (forcing/printed_tool_design).
  const auto body = setup.template_design.region_materials.find("body");
  tool.material_basis = "fitted";
  const auto basis_of = [&](const std::string& table_name) {
    for (const auto& m : setup.materials.materials())
      if (m.name == table_name) return m.basis;
    return std::string();
  };
  if (body != setup.template_design.region_materials.end())
    tool.material_basis = mechanics::least_calibrated(tool.material_basis, basis_of(body->second));
  for (const auto& share : point.mix) {
    const std::string table_name =
        forcing::printed_tip_of(share.material, setup.materials).material;
    tool.material_basis = mechanics::least_calibrated(tool.material_basis, basis_of(table_name));
  }
  return tool;
}

}  // namespace

MixedDesign solved_design(const PredictionSetup& setup, const DesignPoint& point) {
  MixedDesign mixed = mixed_design(point, setup.template_design, setup.materials);
  if (setup.mesh_size > 0) mixed.design.mesh_size = setup.mesh_size;
  if (setup.modes > 0) mixed.design.modes = setup.modes;
  return mixed;
}

SimulatedResponse simulate_response(const PredictionSetup& setup, const DesignPoint& point,
                                    const mechanics::Design* own_design) {
  require_setup(setup);
  MixedDesign mixed =
      own_design ? MixedDesign{*own_design, setup.materials} : solved_design(setup, point);
  if (own_design != nullptr && setup.mesh_size > 0) mixed.design.mesh_size = setup.mesh_size;
  if (own_design != nullptr && setup.modes > 0) mixed.design.modes = setup.modes;
  const mechanics::DesignModel built = mechanics::build_design_model(mixed.design, mixed.materials);
  SimulatedResponse response;
  response.design_name = mixed.design.name;
  response.modal = built.modal;
  for (const auto& h : modal::frequency_response(built.modal, setup.model->frequencies_hz))
    response.response_magnitude.push_back(std::abs(h));
  return response;
}

PredictedTool predict_from_response(const PredictionSetup& setup, const DesignPoint& point,
                                    const std::string& surface, SimulatedResponse response) {
  const FrictionPrediction friction = checked_friction(setup, point, surface);
  return assemble(setup, point, surface, friction, std::move(response));
}

PredictedTool predict_tool(const PredictionSetup& setup, const DesignPoint& point,
                           const std::string& surface, const mechanics::Design* own_design) {
  const FrictionPrediction friction = checked_friction(setup, point, surface);
  return assemble(setup, point, surface, friction, simulate_response(setup, point, own_design));
}

io::ToolEntry predicted_tool_entry(const PredictedTool& tool) {
  io::ToolEntry entry;
  entry.id = "pred:" + to_string(tool.point);
  entry.name = "predicted " + to_string(tool.point);
  entry.kind = "predicted";
  entry.material = tool.point.mix.size() == 1 ? tool.point.mix.front().material : "mix";
  entry.tip_diameter_m = tool.point.tip_diameter_m;
  return entry;
}

io::Pairing predicted_pairing(const PredictedTool& tool, const std::string& threshold_name) {
  io::Pairing pairing;
  pairing.tool = predicted_tool_entry(tool).id;
  pairing.surface = tool.surface;
  io::FrictionDescriptor friction;
  friction.mu = friction.mu_ci_low = friction.mu_ci_high = tool.mu;
  friction.provenance = {"interpolated",
                         "μ linear in tip diameter between measured printed tools, "
                         "weighted by the material fractions"};
  pairing.friction = friction;
  io::VibrationDescriptor vibration;
  vibration.spectrum = tool.spectrum;
  vibration.weighted_mean = tool.vibration.weighted_mean;
  vibration.weighted_power = tool.vibration.weighted_power;
  vibration.band_energies = tool.vibration.band_energies;
  vibration.threshold_curve = threshold_name;
  vibration.provenance = {"predicted", "simulated response of '" + tool.design_name +
                                           "' × fitted surface forcing × interpolated tip and "
                                           "material scaling (Sec. 5.2-5.3)"};
  pairing.vibration = vibration;
  return pairing;
}

}  // namespace nibrig::model::design
