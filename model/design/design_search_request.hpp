// One design search (Sec. 6.2) as every face asks for it: the request, its refusals naming the
// field at fault, and the search run on the faces' predictions. Faces map their options onto the
// request and show its refusals in their own words; what may be refused is refused here, before
// the forcing model is loaded and minutes of predictions begin.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "model/design/design_constraints.hpp"
#include "model/design/design_point.hpp"
#include "model/design/design_response_grid.hpp"
#include "model/design/design_search.hpp"
#include "model/design/prediction_inputs.hpp"
#include "model/io/printer_profile.hpp"
#include "model/space/descriptor_map.hpp"

namespace nibrig::model::design {

// What the candidates are measured against: the space's descriptor map and the targets placed in
// that space, with the names a report gives them (one a placement).
struct DesignSearchTargets {
  std::optional<space::DescriptorMap> descriptor_map;  // none: the search is refused
  std::vector<space::Placement> placements;
  std::vector<std::string> names;
};

struct DesignSearchRequest {
  // Asked for once, after the fields below are checked: a face reads its space file and places its
  // targets only then, so that a bad option is named before a file's error. It may throw to refuse.
  std::function<DesignSearchTargets()> targets;
  std::string surface;                             // the artificial surface the stylus is for
  space::GroupAim aim = space::GroupAim::largest;  // of a group's distances
  DesignConstraints constraints;
  // Two designs: the line search between them; none: the range search over the mix × fitted tips.
  std::optional<std::pair<DesignPoint, DesignPoint>> between;
  std::string first_material = "vero", second_material = "DM85";  // the range search's mix
  // The printer the optimum is for: a line it cannot print is refused before the search.
  std::optional<io::PrinterProfile> printer;
};

// Why a search cannot run: the request's field at fault, and in what() the message in the words
// the face gave for its fields.
class DesignSearchRefused : public std::invalid_argument {
 public:
  enum class Field {
    targets,   // none, unnamed, or placed in a space of other dimensions
    surface,   // none, or one the forcing model does not hold
    space,     // no descriptor map to place the candidates with
    aim,       // not "largest" or "mean"
    between,   // a line no allowed design lies on
    mix,       // not two different materials, or none of their mixes allowed
    min_tip,   // out of range, or above the largest
    max_tip,   // out of range
    allow,     // a material empty or named twice
    cost,      // a cost out of range or without a material
    max_cost,  // out of range, or without costs
    printer,   // a line the printer cannot print
  };
  DesignSearchRefused(Field field, const std::string& what);
  Field field() const noexcept { return field_; }

 private:
  Field field_;
};
using DesignSearchField = DesignSearchRefused::Field;

// The Python arguments' names: "targets", "surface", "space", "aim", "between", "mix",
// "min_tip_mm", "max_tip_mm", "allow", "cost", "max_cost", "printer".
const char* field_name(DesignSearchField field);

// What a face calls each field in its messages. A message may name two fields ("min_tip_mm: 3 mm
// is above max_tip_mm, 2 mm"), so the names go in with the request, as ConstraintNames do.
using DesignSearchNames = std::function<std::string(DesignSearchField)>;

// "largest" or "mean"; anything else is refused as the aim.
space::GroupAim parse_group_aim(const std::string& words,
                                const DesignSearchNames& names = field_name);
const char* group_aim_name(space::GroupAim aim);

// What a search gives besides its candidates, for the faces' reports.
struct DesignSearchOutcome {
  SearchResult result;
  // "along the line vero:1,tip=1mm -> DM85:1,tip=4mm" or "over vero to DM85 x tips 1-4 mm".
  std::string how;
  std::size_t evaluations = 0;  // predictions made
  double seconds = 0.0;
  // A line search: the scan's first and last candidates (indices into result.evaluated), the ends
  // of the segment the constraints allow. Empty for a range search.
  std::vector<std::size_t> line_ends;
  // A search through a design grid (grid_guided_search.hpp): per candidate, whether the FEM solved
  // it; the grid's error measured; the FEM solves made (contenders and checks). Empty, NaN and 0
  // for a search that solved every candidate.
  std::vector<bool> fem_solved;
  double grid_error = std::numeric_limits<double>::quiet_NaN();
  std::size_t fem_solves = 0;
};

// A checked request, ready to run once the predictions are set up.
class DesignSearch {
 public:
  // Checks every field, then asks the request for its targets and checks them. Throws
  // DesignSearchRefused; what request.targets throws.
  explicit DesignSearch(DesignSearchRequest request, const DesignSearchNames& names = field_name);

  const DesignSearchRequest& request() const noexcept { return request_; }
  const DesignSearchTargets& targets() const noexcept { return targets_; }
  const space::DescriptorMap& descriptor_map() const noexcept { return *targets_.descriptor_map; }
  bool group() const noexcept { return targets_.placements.size() > 1; }

  // Searches with the FEM predictions of `inputs` (a second a candidate) over its fitted tips;
  // refuses a surface the forcing model lacks before the first. A stop throws
  // numeric::Cancelled before the next candidate; progress as SearchProgress says.
  DesignSearchOutcome run(const PredictionInputs& inputs, std::stop_token stop = {},
                          const SearchProgress& progress = {}) const;
  // The same through `grid`, a design-response grid of these inputs over the request's mix (the
  // line's designs must mix the grid's materials: else refused as between or mix), the FEM solved
  // only where the grid's error could change the answer (grid_guided_search.hpp); seconds where
  // the above takes a second a candidate. `evaluations` counts the grid's predictions.
  DesignSearchOutcome run(const PredictionInputs& inputs, const DesignResponseGrid& grid,
                          std::stop_token stop = {}, const SearchProgress& progress = {}) const;
  // The same with another predictor (a design-response grid's) and the tips it was fitted over.
  DesignSearchOutcome run(const Predict& predict, double min_tip_m, double max_tip_m,
                          std::stop_token stop = {}, const SearchProgress& progress = {}) const;

 private:
  DesignSearchRequest request_;
  DesignSearchNames names_;
  DesignSearchTargets targets_;

  void check_surface(const forcing::ForcingModel& model) const;
};

}  // namespace nibrig::model::design
