// Order statistics of a signal's samples, by partial sort (the vector is taken by value: the
// caller's samples stay in their order).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace nibrig::model::measure {

// The sample at fraction q (0..1) of the sorted samples, rounded down to a sample (no
// interpolation: thresholds on a long signal, where one sample's step does not matter). v must
// not be empty.
inline double quantile(std::vector<double> v, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// The upper median (the middle sample; of an even count the higher of the two).
inline double median(std::vector<double> v) {
  const std::size_t k = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace nibrig::model::measure
