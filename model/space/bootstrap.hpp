// Bootstrap confidence regions of a fitted space (Sec. 4.5, Fig. 9): resample the judgments with
// replacement, refit, align each refit onto the reference space with Procrustes, and summarise each
// stimulus's cloud of aligned positions by the ellipsoid that encloses a given fraction of it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/numeric/cancellation.hpp"
#include "model/numeric/progress_counter.hpp"
#include "model/space/objective.hpp"

namespace nibrig::model::space {

struct BootstrapOptions {
  int resamples = 1000;
  unsigned seed = 1;     // resample k draws with seed + k: results do not depend on the threads
  unsigned threads = 0;  // 0: one per core; each refit runs on one thread
  // Starts per refit: start 0 begins at the reference space (the resampled optimum lies near it);
  // more starts guard against a resample whose optimum moved to another basin.
  int starts = 1;
  std::vector<double> levels{0.68, 0.95};
  // When set, refits not yet begun are skipped and the bootstrap throws numeric::Cancelled.
  std::stop_token stop;
};

// A stimulus's cloud: the ellipsoid {x : (x − mean)ᵀ covariance⁻¹ (x − mean) ≤ radius[k]²} holds
// the fraction levels[k] of the aligned refits (the empirical quantile of the Mahalanobis
// distance, not a normal-theory radius: the clouds need not be Gaussian).
struct ConfidenceRegion {
  Eigen::VectorXd mean;
  Eigen::MatrixXd covariance;
  std::vector<double> radius;
};

struct BootstrapResult {
  std::vector<double> levels;
  std::vector<ConfidenceRegion> regions;  // one per stimulus
  std::vector<Eigen::MatrixXd> aligned;   // every refit (dims × stimuli), aligned to the reference
  std::vector<double> refit_objectives;
};

// How uncertain a stimulus's place is, in one number: the mean over stimuli of the per-axis sd,
// sqrt(trace(covariance) / dims) of its region (0 for no regions).
double mean_per_axis_sd(const BootstrapResult& result);

// The ellipse of axes (a, b) of a region in the plane of two axes at one level: semi-axes and the
// angle of the first semi-axis from the first axis.
struct PlaneEllipse {
  double semi_axis_1 = 0.0, semi_axis_2 = 0.0, angle_rad = 0.0;
};
// A 1-D region gives its interval as a flat ellipse along the axis (semi-axis 2 and angle 0).
PlaneEllipse plane_ellipse(const ConfidenceRegion& region, std::size_t level, Eigen::Index axis_x = 0,
                           Eigen::Index axis_y = 1);

// The region of a Gaussian placement (descriptor_map.hpp) at each level: its covariance with the
// χ² radius of its dimensions, so that its ellipses compare with the bootstrap's.
ConfidenceRegion gaussian_region(const Eigen::VectorXd& mean, const Eigen::MatrixXd& covariance,
                                 const std::vector<double>& levels);

// Responses are resampled as a whole: the multiset of all (triplet, answer) pairs is drawn with
// replacement to its own size, so triplets with more responses keep their weight. Throws what
// fit_space throws, and std::invalid_argument for resamples < 2, a reference of the wrong shape or
// a level outside (0, 1). `progress` is called as each refit finishes (done 1..resamples), from
// the worker threads but never two at once.
BootstrapResult bootstrap_space(const SpaceProblem& problem, const Eigen::MatrixXd& reference,
                                const BootstrapOptions& options = {},
                                const numeric::Progress& progress = {});

}  // namespace nibrig::model::space
