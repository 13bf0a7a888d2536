#include "ui/panel/space_scene.hpp"

#include <algorithm>

#include "model/design/default_space.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"

namespace nibrig::ui::panel {

namespace space = model::space;

namespace {

// The bundled catalog's surfaces, in its order: each takes the palette's slot of its index. Read
// once (on the first worker that makes a scene); empty when it cannot be read.
const std::vector<std::string>& scene_bundled_surfaces() {
  static const std::vector<std::string> ids = [] {
    std::vector<std::string> out;
    try {
      for (const auto& s : model::io::read_catalog(model::io::or_default({}, model::io::default_catalog)).surfaces)
        out.push_back(s.id);
    } catch (const std::exception&) {
    }
    return out;
  }();
  return ids;
}

// A surface's palette slot from its name alone: the bundled catalog's index, else a hash into the
// slots after the bundled ones (two other surfaces may then share a colour; the legend names both).
std::size_t scene_surface_slot(const std::string& surface) {
  const auto& bundled = scene_bundled_surfaces();
  const auto at = std::find(bundled.begin(), bundled.end(), surface);
  if (at != bundled.end()) return static_cast<std::size_t>(at - bundled.begin());
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a: the same on every machine and run
  for (const unsigned char c : surface) h = (h ^ c) * 1099511628211ULL;
  const std::size_t free = kSurfaceSlots > bundled.size() ? kSurfaceSlots - bundled.size() : kSurfaceSlots;
  return (kSurfaceSlots - free) + static_cast<std::size_t>(h % free);
}

}  // namespace

SpaceScene scene_of(const space::SpaceTools& tools, std::size_t dims, const std::string& title) {
  SpaceScene scene;
  scene.title = title;
  scene.judgment_model = tools.judgment_model;
  scene.model_reason = tools.model_reason;
  for (std::size_t d = 0; d < dims; ++d) scene.axis_names.push_back("axis " + std::to_string(d + 1));
  for (const auto& t : tools.tools) {
    SceneTool s;
    s.choice = {t.tool_id, t.surface_id};
    s.label = t.tool_name + " on " + t.surface_name;
    s.kind = space::kind_name(t.kind);
    s.judged = t.judged;
    if (t.region) {
      s.region = *t.region;
      s.region_levels = tools.levels;
    }
    s.region.mean = t.position;  // the fitted place (a bootstrap region's mean is near it)
    s.mu = t.mu;
    s.noise_sigma = t.noise_sigma;
    for (Eigen::Index k = 0; k < t.descriptors.size(); ++k)
      if (static_cast<std::size_t>(k) < tools.descriptor_names.size())
        s.descriptors.emplace_back(tools.descriptor_names[static_cast<std::size_t>(k)], t.descriptors[k]);
    if (std::find(scene.surfaces.begin(), scene.surfaces.end(), t.surface_id) == scene.surfaces.end()) {
      scene.surfaces.push_back(t.surface_id);
      scene.surface_slots.push_back(scene_surface_slot(t.surface_id));
    }
    scene.tools.push_back(std::move(s));
  }
  return scene;
}

LoadedSpace loaded_space_of(space::SpaceFile s, const std::filesystem::path& catalog_file, const std::string& title) {
  const auto catalog_path = model::io::or_default(catalog_file, model::io::default_catalog);
  const auto catalog = model::io::read_catalog(catalog_path);
  LoadedSpace loaded;
  loaded.scene =
      scene_of(space::space_tools(s, catalog, catalog_path), static_cast<std::size_t>(s.coordinates.rows()), title);
  loaded.map = s.descriptor_map;
  loaded.file = std::move(s);
  return loaded;
}

LoadedSpace load_space_file(const std::filesystem::path& file, const std::filesystem::path& catalog_file) {
  return loaded_space_of(space::read_space_file(file), catalog_file, "space " + file.string());
}

LoadedSpace load_default_space(const model::design::DefaultsOptions& options) {
  const auto cached = model::design::default_space(options);
  LoadedSpace loaded;
  loaded.scene = scene_of(model::design::default_space_tools(cached.value),
                          static_cast<std::size_t>(cached.value.space.coordinates.rows()),
                          "the demo's space: a SIMULATED observer (no human judgments are bundled)");
  loaded.map = cached.value.space.descriptor_map;
  loaded.file = cached.value.space;
  loaded.warnings = cached.warnings;
  return loaded;
}

}  // namespace nibrig::ui::panel
