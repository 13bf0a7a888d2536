// Judgments for the CLI's space tests: every triplet of stimuli "s0", "s1", … at known places on a
// line, judged a number of times by a simulated observer of a given judgment model, written as a
// judgments CSV.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <random>
#include <string>

#include "model/io/triplets.hpp"
#include "model/space/judgment_model.hpp"

namespace nibrig::test {

inline std::filesystem::path write_line_judgments(
    const std::filesystem::path& file, const Eigen::RowVectorXd& places, int judgments,
    unsigned seed, const model::space::JudgmentModel& observer = {}) {
  const Eigen::MatrixXd truth = places;
  const auto n = static_cast<std::size_t>(places.size());
  model::io::TripletSet set;
  for (std::size_t i = 0; i < n; ++i) set.stimuli.push_back("s" + std::to_string(i));
  std::mt19937 generator(seed);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b) {
        if (a == r || b == r) continue;
        std::binomial_distribution<int> answers(
            judgments, model::space::probability_first(observer, truth, r, a, b));
        model::io::Triplet t;
        t.reference = r, t.a = a, t.b = b;
        t.count_a = answers(generator);
        t.count_b = judgments - t.count_a;
        set.triplets.push_back(t);
      }
  model::io::write_triplet_csv(file, set);
  return file;
}

}  // namespace nibrig::test
