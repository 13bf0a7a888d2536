// What the `nibrig space` commands read: judgments as a fitting problem, optionally with the
// catalog descriptors its axes are tied to, and a fitted space with the tools it can place.
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

namespace nibrig::ui::cli {

struct SpaceInputs {
  model::io::TripletSet judgments;
  model::space::SpaceProblem problem;
  // The Sec. 4.5 descriptors of every stimulus for `dims` axes, when a catalog was given.
  std::optional<model::space::DescriptorTable> descriptors;
  std::filesystem::path catalog_file;
};

// Reads judgments (any format) and, when `catalog` is not empty, the descriptors of every judged
// stimulus (named "tool/surface"). λ > 0 without a catalog is refused: it ties the axes to
// descriptors.
SpaceInputs read_space_inputs(const std::filesystem::path& judgments,
                              const std::filesystem::path& catalog, std::size_t dims,
                              double lambda);

// The stimuli of judged queries located in a space: a judged stimulus exactly (zero covariance);
// any other, when a catalog is given and the space has a descriptor map, placed from its
// descriptors. Throws naming the query file and the stimulus otherwise.
class SpaceLocator {
 public:
  SpaceLocator(const model::space::SpaceFile& space, const std::filesystem::path& space_file,
               const std::filesystem::path& catalog_file);
  const model::space::Placement& locate(const std::string& stimulus,
                                        const std::filesystem::path& query_file);
  bool placed(const std::string& stimulus) const;  // located from descriptors, not judged

 private:
  const model::space::SpaceFile& space_;
  std::filesystem::path space_file_, catalog_file_;
  std::optional<model::io::Catalog> catalog_;
  std::map<std::string, model::space::Placement> known_;
  std::map<std::string, bool> placed_;
};

}  // namespace nibrig::ui::cli
