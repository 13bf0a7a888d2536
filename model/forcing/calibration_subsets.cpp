#include "model/forcing/calibration_subsets.hpp"

#include <algorithm>
#include <numeric>
#include <set>

namespace nibrig::model::forcing {

std::vector<std::vector<std::size_t>> calibration_subsets(std::size_t n, std::size_t k,
                                                          std::size_t most, std::mt19937& rng) {
  double count = 1.0;
  for (std::size_t i = 0; i < k; ++i)
    count = count * static_cast<double>(n - i) / static_cast<double>(i + 1);
  std::vector<std::vector<std::size_t>> out;
  if (count <= static_cast<double>(most)) {
    std::vector<bool> chosen(n, false);
    std::fill(chosen.begin(), chosen.begin() + static_cast<std::ptrdiff_t>(k), true);
    do {  // prev_permutation over a k-true mask visits each subset once
      std::vector<std::size_t> subset;
      for (std::size_t i = 0; i < n; ++i)
        if (chosen[i]) subset.push_back(i);
      out.push_back(std::move(subset));
    } while (std::prev_permutation(chosen.begin(), chosen.end()));
    return out;
  }
  std::set<std::vector<std::size_t>> drawn;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  while (drawn.size() < most) {
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::size_t> subset(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k));
    std::sort(subset.begin(), subset.end());
    drawn.insert(std::move(subset));
  }
  return {drawn.begin(), drawn.end()};
}

}  // namespace nibrig::model::forcing
