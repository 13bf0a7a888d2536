#include "model/design/descriptor_uncertainty.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "model/space/catalog_descriptors.hpp"

namespace nibrig::model::design {

namespace {

Eigen::Index index_of(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw std::invalid_argument("no error estimate for descriptor '" + name + "'");
  return static_cast<Eigen::Index>(it - names.begin());
}

// The names of a band count's energies, as a (bands + 1)-dimensional space names them.
std::vector<std::string> band_names(int bands) {
  auto names = space::paper_descriptor_names(static_cast<std::size_t>(bands) + 1);
  names.erase(names.begin());  // μ
  return names;
}

const std::string& friction_name() {
  static const std::string name = space::paper_descriptor_names(1).front();
  return name;
}

}  // namespace

Eigen::MatrixXd DescriptorErrorCovariance::block(const std::vector<std::string>& wanted) const {
  std::vector<Eigen::Index> at;
  for (const auto& name : wanted) at.push_back(index_of(names, name));
  const auto n = static_cast<Eigen::Index>(at.size());
  Eigen::MatrixXd out(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      out(i, j) = covariance(at[static_cast<std::size_t>(i)], at[static_cast<std::size_t>(j)]);
  return out;
}

DescriptorErrorCovariance DescriptorErrorCovariance::without_friction() const {
  DescriptorErrorCovariance out = *this;
  if (out.empty()) return out;
  const Eigen::Index mu = index_of(names, friction_name());
  out.covariance.row(mu).setZero();
  out.covariance.col(mu).setZero();
  return out;
}

std::vector<FrictionInterpolationError> friction_interpolation_errors(const io::Catalog& catalog) {
  struct Measured {
    double tip_m, mu;
    std::string tool;
  };
  // By material and surface, then tip (a later measurement of a tip replaces an earlier one, as
  // in interpolated_friction).
  std::map<std::pair<std::string, std::string>, std::map<double, Measured>> by_material_surface;
  for (const auto& pairing : catalog.pairings) {
    if (!pairing.friction) continue;
    const auto tool = std::find_if(catalog.tools.begin(), catalog.tools.end(),
                                   [&](const auto& t) { return t.id == pairing.tool; });
    // The same tools interpolated_friction interpolates between.
    if (tool == catalog.tools.end() || tool->kind != "printed" || !tool->tip_diameter_m ||
        tool->id.find("_nail") != std::string::npos)
      continue;
    by_material_surface[{tool->material, pairing.surface}][*tool->tip_diameter_m] = {
        *tool->tip_diameter_m, pairing.friction->mu, tool->id};
  }
  std::vector<std::pair<std::size_t, FrictionInterpolationError>> found;  // catalog order
  for (const auto& [key, by_tip] : by_material_surface) {
    // Named, since clang 14 (the sanitizer build's compiler) lets no lambda capture a binding.
    const std::string& surface = key.second;
    std::vector<Measured> tools;
    for (const auto& [tip, measured] : by_tip) tools.push_back(measured);
    for (std::size_t k = 1; k + 1 < tools.size(); ++k) {
      const Measured &lo = tools[k - 1], &mid = tools[k], &hi = tools[k + 1];
      const double w = (mid.tip_m - lo.tip_m) / (hi.tip_m - lo.tip_m);
      const double interpolated = (1 - w) * lo.mu + w * hi.mu;
      const auto order = static_cast<std::size_t>(
          std::find_if(
              catalog.pairings.begin(), catalog.pairings.end(),
              [&](const auto& p) { return p.tool == mid.tool && p.surface == surface; }) -
          catalog.pairings.begin());
      found.push_back({order, {mid.tool, surface, interpolated - mid.mu}});
    }
  }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<FrictionInterpolationError> out;
  for (auto& [order, error] : found) out.push_back(std::move(error));
  return out;
}

DescriptorErrorCovariance descriptor_error_covariance(
    std::span<const forcing::DescriptorError> vibration,
    std::span<const FrictionInterpolationError> friction) {
  if (vibration.empty())
    throw std::invalid_argument(
        "no held-out vibration errors to estimate a predicted tool's descriptor error from");
  DescriptorErrorCovariance out;
  out.names = space::all_paper_descriptor_names();
  const auto n = static_cast<Eigen::Index>(out.names.size());
  out.covariance = Eigen::MatrixXd::Zero(n, n);
  const std::string weighted_mean = space::paper_descriptor_names(2).back();
  for (const auto& e : vibration) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
    r(index_of(out.names, weighted_mean)) = e.log10_weighted_mean;
    for (int k = forcing::kMinDescriptorBands; k <= forcing::kMaxDescriptorBands; ++k) {
      const auto names = band_names(k);
      const auto& values = e.log10_band_energies.at(k);
      for (std::size_t j = 0; j < names.size(); ++j)
        r(index_of(out.names, names[j])) = values.at(j);
    }
    out.covariance += r * r.transpose();
  }
  out.covariance /= static_cast<double>(vibration.size());
  out.vibration_samples = vibration.size();
  double friction_squares = 0.0;
  for (const auto& e : friction) friction_squares += e.error * e.error;
  const Eigen::Index mu = index_of(out.names, friction_name());
  out.covariance(mu, mu) =
      friction.empty() ? 0.0 : friction_squares / static_cast<double>(friction.size());
  out.friction_samples = friction.size();
  return out;
}

}  // namespace nibrig::model::design
