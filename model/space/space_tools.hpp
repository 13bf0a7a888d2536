// Tools in a perceptual space. place_catalog places every catalog pairing from its descriptors
// through the space's descriptor map (Fig. 15), a predicted tool with its descriptor error;
// space_tools lists every tool to draw: the judged stimuli at their fitted coordinates with their
// bootstrap regions, then the other pairings as placed, with their prediction regions.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/io/catalog_file.hpp"
#include "model/space/bootstrap.hpp"
#include "model/space/space_file.hpp"

namespace nibrig::model::space {

// The catalog's tool kinds (io::ToolEntry::kind): measured real tools, printed nibs, commercial
// stylus nibs, predicted designs; unknown for a kind the catalog does not name or a tool it lacks.
enum class ToolKind { real, printed, commercial, predicted, unknown };
ToolKind tool_kind(const std::string& catalog_kind);
const char* kind_name(ToolKind kind);  // "real", "printed", ...

enum class RegionSource {
  bootstrap,       // a judged stimulus's bootstrap region (the space file's regions)
  descriptor_map,  // a placed tool's Gaussian prediction region (descriptor_map.hpp)
  none,            // a judged stimulus of a space fitted without bootstrap
};

struct SpaceTool {
  std::string pairing;               // "tool/surface", the stimulus or catalog pairing name
  std::string tool_id, surface_id;   // the catalog's ids
  std::string tool_name, surface_name;  // the catalog's names for people ("Crayon", "Office paper")
  ToolKind kind = ToolKind::unknown;
  bool judged = false;  // a stimulus of the study (fitted) rather than placed from descriptors
  std::optional<double> mu;  // Coulomb friction; none when the catalog has no friction for it
  // How consistently it was judged: σ_i = exp(η_i) of the space's judgment model (1 = typical);
  // none when the model has no noise per stimulus or the tool was not judged.
  std::optional<double> noise_sigma;
  // The space's descriptors (SpaceTools::descriptor_names), as the fit or the map saw them; empty
  // when the space has none.
  Eigen::VectorXd descriptors;
  Eigen::VectorXd position;  // the space's dimensions; the centre of the ellipses
  RegionSource region_source = RegionSource::none;
  std::optional<ConfidenceRegion> region;
  // The region in the plane of axes 1 and 2 (a flat one along axis 1 in a 1-D space), one per
  // SpaceTools::levels; empty when there is no region.
  std::vector<PlaneEllipse> ellipses;
};

struct SpaceTools {
  std::string judgment_model;  // describe_model of the space's model
  std::string model_reason;    // why that model (the cross-validation that chose it, or "given")
  std::vector<std::string> descriptor_names;
  std::vector<double> levels;  // of every tool's ellipses: the space's bootstrap levels
  std::vector<SpaceTool> tools;  // the stimuli in the space's order, then the placed tools in
                                 // catalog order
};

// A catalog pairing placed from its descriptors.
struct PlacedPairing {
  std::string pairing;  // "tool/surface"
  ToolKind kind = ToolKind::unknown;  // the catalog's kind of its tool; predicted for a prediction
  bool judged = false;  // also a stimulus of the space: placed from its descriptors all the same
  Eigen::VectorXd descriptors;  // the map's descriptors, in its order
  Placement placement;
};

// The error covariance of a predicted tool's descriptors (the map's descriptors, in its order),
// by pairing name: carried into its placement.
using DescriptorErrors = std::map<std::string, Eigen::MatrixXd>;

// Every pairing of the catalog that has every descriptor the space's map needs (both friction and
// vibration), in catalog order, judged or not. Throws std::invalid_argument when the space has no
// descriptor map, or when its descriptors are not the paper's descriptors of some dimensionality
// (catalog_descriptors.hpp), naming them; io::FormatError naming `catalog_file` as
// descriptors_of_catalog does; std::invalid_argument from place_from_descriptors for an error
// covariance of the wrong size.
std::vector<PlacedPairing> place_catalog(const SpaceFile& space, const io::Catalog& catalog,
                                         const std::filesystem::path& catalog_file,
                                         const DescriptorErrors& descriptor_errors = {});

// A stimulus not named "tool/surface" by catalog ids gets what its name gives (kind unknown, no μ).
// The other pairings are place_catalog's, placed only when the space has a descriptor map; without
// a map the list holds the stimuli alone. Throws as place_catalog.
SpaceTools space_tools(const SpaceFile& space, const io::Catalog& catalog,
                       const std::filesystem::path& catalog_file);

}  // namespace nibrig::model::space
