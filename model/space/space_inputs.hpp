// What every face that fits or queries a space reads: judgments as a fitting problem, optionally
// with the catalog descriptors its axes are tied to, and a fitted space with the stimuli it can
// locate — judged ones exactly, others from their descriptors with the map's uncertainty.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/io/triplets.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "model/space/descriptor_map.hpp"
#include "model/space/objective.hpp"
#include "model/space/space_file.hpp"

namespace nibrig::model::space {

struct SpaceInputs {
  io::TripletSet judgments;
  SpaceProblem problem;
  // The Sec. 4.5 descriptors of every stimulus for `dims` axes, when a catalog was given.
  std::optional<DescriptorTable> descriptors;
  std::filesystem::path catalog_file;
};

// Reads judgments (any format) and, when `catalog` is not empty, the descriptors of every judged
// stimulus (named "tool/surface"). λ > 0 without a catalog, or λ < 0, is refused
// (std::invalid_argument): λ ties the axes to descriptors.
SpaceInputs read_space_inputs(const std::filesystem::path& judgments,
                              const std::filesystem::path& catalog, std::size_t dims,
                              double lambda);
// The same from judgments already read (a script fitting several spaces to one file reads it once).
SpaceInputs space_inputs(io::TripletSet judgments, const std::filesystem::path& catalog,
                         std::size_t dims, double lambda);

// The stimuli of judged queries located in a space: a judged stimulus exactly (zero covariance);
// any other, when a catalog is given and the space has a descriptor map, placed from its
// descriptors. Throws naming the query file and the stimulus otherwise.
class StimulusLocator {
 public:
  StimulusLocator(const SpaceFile& space, const std::filesystem::path& space_file,
               const std::filesystem::path& catalog_file);
  const Placement& locate(const std::string& stimulus,
                                        const std::filesystem::path& query_file);
  bool placed(const std::string& stimulus) const;  // located from descriptors, not judged

 private:
  const SpaceFile& space_;
  std::filesystem::path space_file_, catalog_file_;
  std::optional<io::Catalog> catalog_;
  std::map<std::string, Placement> known_;
  std::map<std::string, bool> placed_;
};

// The probability that each query's first candidate is chosen (objective.hpp), with its sd: exact
// (sd 0) when all three stimuli are judged ones, else the average over draws of their placements'
// uncertainty (seeded, so the same queries give the same numbers).
struct QueryPrediction {
  double p = 0.0, sd = 0.0;
};
inline constexpr int kUncertaintySamples = 2000;  // sd of p to about ±2 % of itself
std::vector<QueryPrediction> predict_queries(const SpaceFile& space, const io::TripletSet& queries,
                                             StimulusLocator& locator,
                                             const std::filesystem::path& query_file);

}  // namespace nibrig::model::space
