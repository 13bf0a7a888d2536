// A space asked about judged triplets and scored against their answers (`nibrig space evaluate`,
// nibrig.space.Space.evaluate), and the cross-validation of spaces of several dimensions, weights
// and judgment models over one judgments file (`nibrig space validate`, nibrig.space.validate).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

#include "model/io/triplets.hpp"
#include "model/numeric/progress_counter.hpp"
#include "model/space/dimension_scan.hpp"
#include "model/space/prediction_scores.hpp"
#include "model/space/space_file.hpp"
#include "model/space/statistics.hpp"

namespace nibrig::model::space {

struct SpaceEvaluation {
  PredictionScores scores;
  std::size_t placed_from_descriptors = 0;  // judged stimuli the space had not seen
};

// Stimuli the space was not fitted to are placed from `catalog`'s descriptors (none: refused,
// naming the stimulus and `judged_file`); the files name the space and judgments in errors.
SpaceEvaluation evaluate_space(const SpaceFile& space, const std::filesystem::path& space_file,
                               const io::TripletSet& judged, const std::filesystem::path& judged_file,
                               const std::filesystem::path& catalog);

struct Validation {
  std::size_t triplets = 0, responses = 0;
  std::vector<DimensionScanPoint> points;  // one per dims × lambda × model, in that order
  // When every stimulus name ends in a number (Salmon's items are positions on a 1-D continuum) and
  // 1 dimension was asked: the rank correlation of a 1-D fit of all judgments with those numbers.
  std::optional<Correlation> rank_correlation_with_names;
};

// `scan` says the dimensions, weights, models, folds, starts, seed and threads; `descriptors` is
// the catalog the axes are tied to, needed for a weight above 0 (std::invalid_argument otherwise).
// The fits honour scan.cross_validation.fit.stop.
Validation validate_space_file(const std::filesystem::path& judgments,
                               const std::filesystem::path& descriptors,
                               const DimensionScanOptions& scan,
                               const numeric::Progress& progress = {});
// The same on judgments already read (or made from arrays).
Validation validate_space(io::TripletSet judgments, const std::filesystem::path& descriptors,
                          const DimensionScanOptions& scan, const numeric::Progress& progress = {});

}  // namespace nibrig::model::space
