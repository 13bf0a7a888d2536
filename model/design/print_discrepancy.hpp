// What the model misses where prints were measured, carried to the designs near them: a design
// loop's correction of its predictions (design_loop.hpp). The forcing refit takes a print in as
// one exemplar among dozens, so it barely moves where the print showed the model wrong; this does.
//
// The miss δ(x) = measured − predicted descriptors of a design x = (fraction of the range's second
// material, tip) is a Gaussian process: δ ~ GP(0, k(x, x')·C), C the predictions' cross-validated
// descriptor error (what a print the model has not seen misses by, descriptor_uncertainty.hpp), k a
// squared-exponential correlation over the design range. A measured print observes δ with the
// measurement's own noise R (a print recorded twice: measurement_descriptor_noise). Far from every
// print the correction is 0 and its covariance C, as without it; at a print it is the print's miss,
// down to R.
//
// C is cross-validated on the paper's prints; a lab's prints may miss by more (another batch,
// finish or printer). So C is scaled by s ≥ 1, the scale under which the prints' residuals are most
// likely (maximum likelihood of N(0, s·K ⊗ C + I ⊗ R)): never below the cross-validated error,
// larger when the prints say so.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/design/design_point.hpp"
#include "model/io/catalog_file.hpp"

namespace nibrig::model::design {

struct PrintResidual {
  DesignPoint point;
  Eigen::VectorXd measured_minus_predicted;  // descriptors, in the prior's order
};

// Correlation lengths: half the fraction range and half the paper's 1-4 mm tips. The model's
// misses come from whole material curves, moduli and the mixing rule, which change smoothly over
// the range, so a print informs its neighbours across a good part of it; the design loop's
// simulated world (tests/model/design/design_loop_world_test.cpp) reports the loop with these.
inline constexpr double kDiscrepancyFractionLength = 0.5;
inline constexpr double kDiscrepancyTipLengthM = 0.0015;
// The largest scale of C the prints may ask for (a standard deviation 100 times the
// cross-validated one): beyond it a print is a different material, not a miss.
inline constexpr double kLargestModelErrorScale = 1e4;

struct DiscrepancyPrior {
  std::vector<std::string> names;     // descriptors
  Eigen::MatrixXd model_error;        // C, names × names
  Eigen::MatrixXd measurement_noise;  // R, names × names
  std::string second_material;        // the fraction axis: this material's share
  double fraction_length = kDiscrepancyFractionLength, tip_length_m = kDiscrepancyTipLengthM;
};

struct DescriptorCorrection {
  Eigen::VectorXd mean;        // added to a prediction's descriptors
  Eigen::MatrixXd covariance;  // the corrected prediction's error, in place of C
};

class PrintDiscrepancy {
 public:
  // Throws std::invalid_argument for matrices of the wrong size, not symmetric or with a negative
  // diagonal, a residual of the wrong length or not finite, or lengths that are not positive.
  PrintDiscrepancy(DiscrepancyPrior prior, std::vector<PrintResidual> prints);

  DescriptorCorrection at(const DesignPoint& point) const;
  double model_error_scale() const { return scale_; }

 private:
  double correlation(const DesignPoint& a, const DesignPoint& b) const;

  DiscrepancyPrior prior_;
  std::vector<PrintResidual> prints_;
  Eigen::MatrixXd solve_;  // Σ⁻¹ of the stacked observations (prints × descriptors)
  Eigen::VectorXd alpha_;  // Σ⁻¹ r
  double scale_ = 1.0;
};

// A measurement's own descriptor noise, in `names`' order (μ first, as every space's): for the
// vibration, half the mean outer product of the descriptor differences between the catalog's
// prints recorded twice ("<print>_nail1" and "_nail2" on one surface, as
// forcing::nail_pair_repeatability pairs them); for μ, which those were recorded without, the mean
// variance of the catalog's measured μ from their 95 % intervals. Throws std::invalid_argument when
// the catalog holds no such pair.
Eigen::MatrixXd measurement_descriptor_noise(const io::Catalog& catalog,
                                             const std::vector<std::string>& names);

}  // namespace nibrig::model::design
