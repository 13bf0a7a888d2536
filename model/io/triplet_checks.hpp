// The checks every triplet reader and the writer apply to one triplet, so that all sources reject
// the same things with the same words.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/io/triplets.hpp"

namespace nibrig::model::io {

// What is wrong with `triplet` given the stimulus names: an index out of range, a stimulus used
// twice (a self-triplet), a negative count, or no response at all. nullopt when it is fine.
std::optional<std::string> triplet_problem(const Triplet& triplet,
                                           const std::vector<std::string>& stimuli);

}  // namespace nibrig::model::io
