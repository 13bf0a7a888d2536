#include "ui/panel/space_scene.hpp"

#include <algorithm>
#include <stdexcept>

#include "model/space/catalog_descriptors.hpp"
#include "model/space/descriptor_map.hpp"

namespace nibrig::ui::panel {

namespace {

namespace space = model::space;

ToolChoice choice_of(const std::string& stimulus) {
  const auto slash = stimulus.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == stimulus.size())
    throw std::invalid_argument("space stimulus '" + stimulus + "' is not named tool/surface");
  return {stimulus.substr(0, slash), stimulus.substr(slash + 1)};
}

// Name, kind and μ of a tool on a surface from the catalog (the id itself when it has none).
void describe(SceneTool& t, const model::io::Catalog& catalog) {
  std::string tool = t.choice.tool, surface = t.choice.surface;
  for (const auto& e : catalog.tools)
    if (e.id == t.choice.tool) tool = e.name, t.kind = e.kind;
  for (const auto& e : catalog.surfaces)
    if (e.id == t.choice.surface) surface = e.name;
  if (t.kind.empty() || t.kind == "unknown") t.kind = "real";
  t.label = tool + " on " + surface;
  for (const auto& p : catalog.pairings)
    if (p.tool == t.choice.tool && p.surface == t.choice.surface && p.friction) t.mu = p.friction->mu;
}

}  // namespace

SpaceScene scene_of(const space::SpaceFile& file, const model::io::Catalog& catalog,
                    const std::filesystem::path& catalog_file, const std::string& title) {
  SpaceScene scene;
  scene.title = title;
  const auto dims = static_cast<std::size_t>(file.coordinates.rows());
  for (std::size_t d = 0; d < dims; ++d) scene.axis_names.push_back("axis " + std::to_string(d + 1));
  const std::vector<double> levels = file.region_levels.empty() ? std::vector<double>{0.68, 0.95} : file.region_levels;
  for (std::size_t i = 0; i < file.stimuli.size(); ++i) {
    SceneTool t;
    t.choice = choice_of(file.stimuli[i]);
    t.judged = true;
    if (i < file.regions.size()) {
      t.region = file.regions[i];
      t.region_levels = file.region_levels;
    }
    t.region.mean = file.coordinates.col(static_cast<Eigen::Index>(i));  // its fitted place
    for (std::size_t k = 0; k < file.descriptor_names.size(); ++k)
      t.descriptors.emplace_back(file.descriptor_names[k],
                                 file.descriptors(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)));
    describe(t, catalog);
    scene.tools.push_back(std::move(t));
  }
  if (file.descriptor_map) {
    const space::DescriptorTable all = space::descriptors_of_catalog(catalog, catalog_file, dims);
    if (all.names == file.descriptor_map->descriptor_names) {
      for (std::size_t r = 0; r < all.rows.size(); ++r) {
        if (std::find(file.stimuli.begin(), file.stimuli.end(), all.rows[r]) != file.stimuli.end()) continue;
        SceneTool t;
        t.choice = choice_of(all.rows[r]);
        const Eigen::VectorXd z = all.values.row(static_cast<Eigen::Index>(r)).transpose();
        const space::Placement p = space::place_from_descriptors(*file.descriptor_map, z);
        t.region = space::gaussian_region(p.mean, p.covariance, levels);
        t.region_levels = levels;
        for (std::size_t k = 0; k < all.names.size(); ++k) t.descriptors.emplace_back(all.names[k], z[static_cast<Eigen::Index>(k)]);
        describe(t, catalog);
        scene.tools.push_back(std::move(t));
      }
    }
  }
  for (const auto& t : scene.tools)
    if (std::find(scene.surfaces.begin(), scene.surfaces.end(), t.choice.surface) == scene.surfaces.end())
      scene.surfaces.push_back(t.choice.surface);
  return scene;
}

}  // namespace nibrig::ui::panel
