// Placing a tool in the perceptual space from its physical descriptors alone (Sec. 4.4, 6.1): the
// axes were fitted to correlate with the descriptors, so a linear map from descriptors to
// coordinates, learnt by least squares over the judged stimuli, places a new tool without a new
// experiment. Its uncertainty is the regression's prediction covariance.
#pragma once

#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

#include "model/space/judgment_model.hpp"

namespace nibrig::model::space {

// coordinates ≈ B · [1, z]ᵀ with z the standardised descriptors (z = (x − mean) / scale).
struct DescriptorMap {
  std::vector<std::string> descriptor_names;
  Eigen::VectorXd descriptor_mean, descriptor_scale;  // per descriptor
  Eigen::MatrixXd coefficients;                       // dims × (1 + descriptors)
  Eigen::MatrixXd design_inverse;       // (ZᵀZ)⁻¹ of the design matrix Z = [1, z]
  Eigen::MatrixXd residual_covariance;  // dims × dims, unbiased (n − 1 − descriptors degrees)
  std::vector<double> r_squared;        // per axis
  std::size_t samples = 0;
};

// coordinates: dims × n stimuli; descriptors: n × p. Throws std::invalid_argument for rows that do
// not match the stimuli, names that do not match the columns, non-finite values, a constant
// descriptor, or n ≤ p + 1 (no residual degree of freedom to estimate the uncertainty).
DescriptorMap fit_descriptor_map(const Eigen::MatrixXd& coordinates,
                                 const Eigen::MatrixXd& descriptors,
                                 const std::vector<std::string>& names);

// A position with its uncertainty: mean and covariance (dims × dims) of where the tool lies.
struct Placement {
  Eigen::VectorXd mean;
  Eigen::MatrixXd covariance;
};

// How far a placed tool's descriptor may lie from the judged stimuli's, in their standard
// deviations: the map is learnt within a few, so one beyond a million is a damaged value or a unit
// slip, and 1e308 would place the tool at infinity.
inline constexpr double kFarthestStandardisedDescriptor = 1e6;

// The prediction covariance Σ·(1 + z₀ᵀ(ZᵀZ)⁻¹z₀) holds both the scatter of judged stimuli about
// the map and the uncertainty of the map itself (larger far from the judged descriptors). Throws
// std::invalid_argument naming the descriptor for a wrong length, a non-finite value or one
// farther than kFarthestStandardisedDescriptor standard deviations.
Placement place_from_descriptors(const DescriptorMap& map, const Eigen::VectorXd& descriptors);

// The same for descriptors that are themselves uncertain (a predicted tool's): their error
// covariance (descriptors × descriptors, in the map's descriptor units) carried through the map,
// J·Σ·Jᵀ with J = ∂coordinates/∂descriptors = B[:, 1:]·diag(1/scale), is added to the prediction
// covariance. Exact, the map being linear. Throws as above, and for a covariance of the wrong
// size, not symmetric or with a negative or non-finite diagonal.
Placement place_from_descriptors(const DescriptorMap& map, const Eigen::VectorXd& descriptors,
                                 const Eigen::MatrixXd& descriptor_covariance);

// P(a chosen as closer to the reference than b) when any of the three is uncertain: mean and
// standard deviation over `samples` draws of the uncertain positions (a judged stimulus has a zero
// covariance). Deterministic for a given generator state.
struct UncertainProbability {
  double mean = 0.0, sd = 0.0;
};
// The judgment model's typical noise stands for theirs (typical_log_sigma): a placed tool was never
// judged.
UncertainProbability uncertain_probability_first(const Placement& reference, const Placement& a,
                                                 const Placement& b, const JudgmentModel& model, int samples,
                                                 std::mt19937_64& generator);

// The distance between two uncertain positions: between their means, and its standard deviation
// over `samples` draws of both (a judged stimulus has a zero covariance). Throws
// std::invalid_argument for placements of different dimensions or fewer than 2 samples.
struct UncertainDistance {
  double between_means = 0.0, sd = 0.0;
};
UncertainDistance uncertain_distance(const Placement& a, const Placement& b, int samples,
                                     std::mt19937_64& generator);

// The distance of one uncertain position to a group of them (one design for several tools): the
// largest or the mean of its distances to each. `aggregate` is that of the distances between the
// means, its sd over `samples` joint draws of every position (the design's draw shared by all its
// distances); `each` is every target's own distance and sd from the same draws. Throws
// std::invalid_argument for no targets, placements of different dimensions or fewer than 2 samples.
enum class GroupAim { largest, mean };
struct GroupDistance {
  UncertainDistance aggregate;
  std::vector<UncertainDistance> each;
};
GroupDistance uncertain_group_distance(const Placement& a, const std::vector<Placement>& targets, GroupAim aim,
                                       int samples, std::mt19937_64& generator);

}  // namespace nibrig::model::space
