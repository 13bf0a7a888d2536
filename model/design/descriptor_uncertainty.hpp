// How uncertain a predicted tool's descriptors are, so that its place in the perceptual space
// (Fig. 15, design search) is not drawn as if they had been measured.
//
// Estimated by cross-validation, from what the predictions actually missed:
// - vibration: each printed exemplar held out of the forcing fit and predicted (the forcing
//   model's held_out_descriptor_errors), log10(predicted / measured) of the weighted mean and of
//   every band energy;
// - friction: each printed tool with a middle tip (a measured diameter between two others of its
//   material on its surface), its μ interpolated linearly from those two neighbours, as a predicted
//   tool's μ is (predicted_tool.hpp), minus its measured μ.
// The covariance is the second moment of these errors about zero, not about their mean: a bias
// the predictions share is an error of a predicted tool's place too. Friction and vibration errors
// come from different tools and different interpolations, so their cross terms are zero.
//
// A predicted tool whose μ was measured (one material, a measured tip diameter) has no friction
// error beyond the measurement's own, which the descriptor map's scatter already holds. A mix of
// materials takes the tip interpolation's friction error as its own: μ of a mix is interpolated
// too (linearly in the fractions), and the data hold no measured mix to check it against.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/descriptor_error.hpp"
#include "model/io/catalog_file.hpp"

namespace nibrig::model::design {

struct DescriptorErrorCovariance {
  std::vector<std::string> names;  // space::all_paper_descriptor_names(); empty: no estimate
  Eigen::MatrixXd covariance;      // names × names, in descriptor units (μ, log10)
  std::size_t vibration_samples = 0, friction_samples = 0;

  bool empty() const { return names.empty(); }
  // The sub-matrix over `wanted`, in that order. Throws std::invalid_argument naming a descriptor
  // it has no error for.
  Eigen::MatrixXd block(const std::vector<std::string>& wanted) const;
  // The same covariance with the friction variance zeroed (a measured μ).
  DescriptorErrorCovariance without_friction() const;
};

struct FrictionInterpolationError {
  std::string tool, surface;
  double error = 0.0;  // interpolated − measured μ
};

// The printed tools (not their nail-test variants) with a middle tip, in catalog order.
std::vector<FrictionInterpolationError> friction_interpolation_errors(const io::Catalog& catalog);

// Throws std::invalid_argument when there are no vibration errors (nothing to estimate from).
// No friction errors leave the friction variance 0 (friction_samples says so).
DescriptorErrorCovariance descriptor_error_covariance(
    std::span<const forcing::DescriptorError> vibration,
    std::span<const FrictionInterpolationError> friction);

}  // namespace nibrig::model::design
