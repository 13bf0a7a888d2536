// A fitted perceptual space on disk (space.json, format "nibrig-space" version 1): stimulus names,
// coordinates, the model's scale, λ, fit statistics and provenance; what `nibrig space fit` writes
// and `nibrig space predict` reads.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace nibrig::model::space {

struct SpaceFile {
  std::vector<std::string> stimuli;
  Eigen::MatrixXd coordinates;  // dims × stimuli
  double scale = 0.0;           // s of P = Φ(−s·d)
  double lambda = 0.0;
  double objective = 0.0, negative_log_likelihood = 0.0;
  std::vector<double> start_objectives;
  std::size_t triplets = 0, responses = 0;
  std::string judgments;  // the file fitted
};

void write_space_file(const std::filesystem::path& file, const SpaceFile& space);
// Throws io::FormatError naming the file and field (wrong format, coordinates that do not match
// the stimuli, non-finite numbers).
SpaceFile read_space_file(const std::filesystem::path& file);

}  // namespace nibrig::model::space
