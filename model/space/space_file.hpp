// A fitted perceptual space on disk (space.json, format "nibrig-space" version 1): stimulus names,
// coordinates, the model's scale, λ, fit statistics and provenance; optionally the descriptors the
// axes were tied to, the map that places new tools from descriptors, and bootstrap confidence
// regions. What `nibrig space fit` writes and `space predict`, `space embed` and the plots read.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/space/bootstrap.hpp"
#include "model/space/descriptor_map.hpp"
#include "model/space/judgment_model.hpp"

namespace nibrig::model::space {

// The most dimensions a space file may have (as `space fit --dims`), and the largest coordinate
// magnitude a reader takes: fitted spaces span a few units.
inline constexpr long long kMaxSpaceDims = 10;
inline constexpr double kMaxCoordinate = 1e3;

struct SpaceFile {
  std::vector<std::string> stimuli;
  Eigen::MatrixXd coordinates;  // dims × stimuli
  // How distances become judgments (its family, scale, lapse and noises), why this model (given or
  // chosen by cross-validation), and every candidate's held-out scores when chosen.
  JudgmentModel model;
  std::string model_reason;
  std::vector<ModelScore> model_scores;
  double lambda = 0.0;
  double objective = 0.0, negative_log_likelihood = 0.0;
  std::vector<double> start_objectives;
  std::size_t triplets = 0, responses = 0;
  std::string judgments;  // the file fitted
  double seconds = 0.0;   // wall time of the fit

  // The descriptors (stimuli × names) and where they came from; empty names when none.
  std::vector<std::string> descriptor_names;
  Eigen::MatrixXd descriptors;
  std::string descriptor_source;
  std::optional<DescriptorMap> descriptor_map;

  // Bootstrap confidence regions, one per stimulus, at region_levels; empty when not computed.
  std::vector<double> region_levels;
  std::vector<ConfidenceRegion> regions;
  int bootstrap_resamples = 0;
};

void write_space_file(const std::filesystem::path& file, const SpaceFile& space);
// Throws io::FormatError naming the file and field (wrong format, coordinates that do not match
// the stimuli, non-finite numbers).
SpaceFile read_space_file(const std::filesystem::path& file);

// The file's text and its reading from text, for a space kept in memory (a pickled one): the same
// checks, `file` naming the text in errors. Doubles keep every digit, so a space read back predicts
// exactly what it did.
std::string space_file_text(const SpaceFile& space, const std::filesystem::path& file);
SpaceFile parse_space_file(const std::string& text, const std::filesystem::path& file);

}  // namespace nibrig::model::space
