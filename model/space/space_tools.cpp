#include "model/space/space_tools.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "model/space/catalog_descriptors.hpp"

namespace nibrig::model::space {

namespace {

const std::vector<std::pair<ToolKind, const char*>> kKinds{{ToolKind::real, "real"},
                                                           {ToolKind::printed, "printed"},
                                                           {ToolKind::commercial, "commercial"},
                                                           {ToolKind::predicted, "predicted"},
                                                           {ToolKind::unknown, "unknown"}};

std::vector<PlaneEllipse> ellipses_of(const ConfidenceRegion& region) {
  std::vector<PlaneEllipse> out;
  for (std::size_t k = 0; k < region.radius.size(); ++k) out.push_back(plane_ellipse(region, k));
  return out;
}

// What the catalog says of a pairing's tool and surface; the ids alone when it has no entry.
void describe(SpaceTool& t, const io::Catalog& catalog) {
  t.tool_name = t.tool_id;
  t.surface_name = t.surface_id;
  for (const auto& tool : catalog.tools)
    if (tool.id == t.tool_id) {
      t.tool_name = tool.name;
      t.kind = tool_kind(tool.kind);
    }
  for (const auto& surface : catalog.surfaces)
    if (surface.id == t.surface_id) t.surface_name = surface.name;
  for (const auto& p : catalog.pairings)
    if (p.tool == t.tool_id && p.surface == t.surface_id && p.friction) t.mu = p.friction->mu;
}

}  // namespace

ToolKind tool_kind(const std::string& catalog_kind) {
  for (const auto& [kind, name] : kKinds)
    if (catalog_kind == name) return kind;
  return ToolKind::unknown;
}

const char* kind_name(ToolKind kind) {
  for (const auto& [k, name] : kKinds)
    if (k == kind) return name;
  return "unknown";
}

std::vector<PlacedPairing> place_catalog(const SpaceFile& space, const io::Catalog& catalog,
                                         const std::filesystem::path& catalog_file,
                                         const DescriptorErrors& descriptor_errors) {
  if (!space.descriptor_map)
    throw std::invalid_argument(
        "the space has no descriptor map: placing tools needs a space fitted with descriptors");
  const DescriptorMap& map = *space.descriptor_map;
  const std::size_t count = map.descriptor_names.size();
  if (count < 1 || count > 6 || paper_descriptor_names(count) != map.descriptor_names) {
    std::string names;
    for (const auto& n : map.descriptor_names) names += (names.empty() ? "" : ", ") + n;
    throw std::invalid_argument(
        "the space's descriptor map uses [" + names +
        "]; placing catalog tools needs the paper's descriptors of one dimensionality "
        "(model/space/catalog_descriptors.hpp)");
  }
  const DescriptorTable all = descriptors_of_catalog(catalog, catalog_file, count);
  std::vector<PlacedPairing> out;
  out.reserve(all.rows.size());
  for (std::size_t i = 0; i < all.rows.size(); ++i) {
    PlacedPairing p;
    p.pairing = all.rows[i];
    p.judged =
        std::find(space.stimuli.begin(), space.stimuli.end(), p.pairing) != space.stimuli.end();
    const std::string tool_id = p.pairing.substr(0, p.pairing.find('/'));
    for (const auto& tool : catalog.tools)
      if (tool.id == tool_id) p.kind = tool_kind(tool.kind);
    p.descriptors = all.values.row(static_cast<Eigen::Index>(i)).transpose();
    const auto error = descriptor_errors.find(p.pairing);
    p.placement = error == descriptor_errors.end()
                      ? place_from_descriptors(map, p.descriptors)
                      : place_from_descriptors(map, p.descriptors, error->second);
    out.push_back(std::move(p));
  }
  return out;
}

SpaceTools space_tools(const SpaceFile& space, const io::Catalog& catalog,
                       const std::filesystem::path& catalog_file) {
  SpaceTools out;
  out.descriptor_names = space.descriptor_names;
  out.judgment_model = describe_model(space.model);
  out.model_reason = space.model_reason;
  // Placed tools' ellipses are drawn at the bootstrap's levels so that the two kinds compare; a
  // space without bootstrap takes the demo's 68 % / 95 %.
  out.levels = space.region_levels.empty() ? std::vector<double>{0.68, 0.95} : space.region_levels;

  for (std::size_t i = 0; i < space.stimuli.size(); ++i) {
    SpaceTool t;
    t.pairing = space.stimuli[i];
    const auto slash = t.pairing.find('/');
    t.tool_id = t.pairing.substr(0, slash);
    t.surface_id = slash == std::string::npos ? std::string() : t.pairing.substr(slash + 1);
    describe(t, catalog);
    t.judged = true;
    const auto column = static_cast<Eigen::Index>(i);
    t.position = space.coordinates.col(column);
    if (space.model.log_noise.size() > column) t.noise_sigma = std::exp(space.model.log_noise(column));
    if (space.descriptors.size() > 0) t.descriptors = space.descriptors.row(column).transpose();
    if (!space.regions.empty()) {
      t.region_source = RegionSource::bootstrap;
      t.region = space.regions[i];
      t.ellipses = ellipses_of(*t.region);
    }
    out.tools.push_back(std::move(t));
  }
  if (!space.descriptor_map) return out;

  for (PlacedPairing& placed : place_catalog(space, catalog, catalog_file)) {
    if (placed.judged) continue;
    SpaceTool t;
    t.pairing = std::move(placed.pairing);
    const auto slash = t.pairing.find('/');
    t.tool_id = t.pairing.substr(0, slash);
    t.surface_id = t.pairing.substr(slash + 1);
    describe(t, catalog);
    t.descriptors = std::move(placed.descriptors);
    t.position = placed.placement.mean;
    t.region_source = RegionSource::descriptor_map;
    t.region = gaussian_region(placed.placement.mean, placed.placement.covariance, out.levels);
    t.ellipses = ellipses_of(*t.region);
    out.tools.push_back(std::move(t));
  }
  return out;
}

}  // namespace nibrig::model::space
