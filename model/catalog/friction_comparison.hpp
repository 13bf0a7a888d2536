// How a catalog's friction fits compare with the authors' own recipe on the same recordings (the
// mean of rows 5000-20000, measure::upstream_mu): the range and median of each and their mean
// absolute difference, which `catalog build` reports beside the paper's stated 0.13-0.33.
#pragma once

#include <vector>

#include "model/catalog/analysis.hpp"

namespace nibrig::model::catalog {

struct FrictionComparison {
  double fit_min = 0, fit_max = 0, fit_median = 0;
  double upstream_min = 0, upstream_max = 0, upstream_median = 0;
  double mean_abs_difference = 0;
};

// The median is the upper middle value of an even count, as a person reading a list would pick.
// Throws std::invalid_argument for no analyses.
FrictionComparison compare_with_upstream(const std::vector<FrictionAnalysis>& friction);

}  // namespace nibrig::model::catalog
