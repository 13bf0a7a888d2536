// Every tool a face draws in a perceptual space, in one list: the judged stimuli at their fitted
// coordinates with their bootstrap regions, and every other catalog pairing placed from its
// descriptors with the descriptor map's prediction uncertainty (Fig. 9 and 15 in one).
#pragma once

#include <Eigen/Core>
#include <filesystem>
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

// A stimulus not named "tool/surface" by catalog ids gets what its name gives (kind unknown, no μ).
// Pairings are placed only when the space has a descriptor map and the catalog pairing has every
// descriptor the map needs (both friction and vibration); without a map the list holds the
// stimuli alone. Throws std::invalid_argument when the map's descriptors are not the paper's
// descriptors of some dimensionality (catalog_descriptors.hpp), naming them; io::FormatError
// naming `catalog_file` as descriptors_of_catalog does.
SpaceTools space_tools(const SpaceFile& space, const io::Catalog& catalog,
                       const std::filesystem::path& catalog_file);

}  // namespace nibrig::model::space
