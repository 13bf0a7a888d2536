// Which k of n things a calibration study tries (k reference tools, k surfaces): every subset when
// there are few, else a bounded number drawn at random, so that a study's cost stays bounded and
// its result is reproducible from the seed.
#pragma once

#include <cstddef>
#include <random>
#include <vector>

namespace nibrig::model::forcing {

// Every k-subset of {0, …, n−1} (ascending indices) when C(n, k) ≤ most; else `most` distinct ones
// drawn with `rng`. Needs 1 ≤ k ≤ n and most ≥ 1.
std::vector<std::vector<std::size_t>> calibration_subsets(std::size_t n, std::size_t k,
                                                          std::size_t most, std::mt19937& rng);

}  // namespace nibrig::model::forcing
