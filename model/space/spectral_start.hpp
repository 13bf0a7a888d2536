// A starting space from the judgments themselves, for start 0 of a fit: classical (Torgerson)
// multidimensional scaling of a dissimilarity per stimulus pair read off the triplets. A 1-D fit
// from random starts often stops with stimuli in the wrong order (they cannot pass each other on a
// line): on Salmon's 300 alien eggs, 16 random starts' best ranged over 4,645 to 5,260 nats between
// seeds, and this start reaches 4,646 to 4,650 whatever its scale (numpy prototype, probit). On
// Lagunas 3-D it starts in the best basin random starts find (43,290.5).
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "model/space/objective.hpp"

namespace nibrig::model::space {

// Above this many stimuli the dense eigensolver (O(n³)) is not worth a start: no spectral start.
inline constexpr std::size_t kSpectralStartMaxStimuli = 2000;

// dims × stimuli, centred, with an RMS radius of `radius`. A pair's dissimilarity is the share of
// answers that took the other candidate over it, (far + ½)/(near + far + 1), where it was ever a
// reference and candidate; the mean of those where it never was. Empty (0 × 0) when the problem has
// more than kSpectralStartMaxStimuli stimuli or its dissimilarities have fewer than dims positive
// directions.
Eigen::MatrixXd spectral_start(const SpaceProblem& problem, double radius);

}  // namespace nibrig::model::space
