#include "model/design/bundled_defaults.hpp"

#include <chrono>
#include <functional>
#include <optional>
#include <stdexcept>
#include <utility>

#include "model/design/default_forcing.hpp"
#include "model/design/default_space.hpp"
#include "model/design/design_grid_file.hpp"
#include "model/design/prediction_inputs.hpp"
#include "model/design/stylus_modes.hpp"
#include "model/io/bundled_assets.hpp"

namespace nibrig::model::design {

namespace {

template <typename T>
BundledDefault timed(const std::string& what, const std::function<Cached<T>()>& make) {
  const auto start = std::chrono::steady_clock::now();
  const Cached<T> made = make();
  return {what, made.file, made.computed,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

}  // namespace

std::vector<BundledDefault> compute_bundled_defaults(const DefaultsOptions& options) {
  if (!options.cache_dir.empty())
    throw std::invalid_argument("the bundled defaults go to the user cache (NIBRIG_CACHE), not " +
                                options.cache_dir.string());
  std::vector<BundledDefault> out;
  out.push_back(timed<DefaultSpace>("default space", [&] { return default_space(options); }));
  std::optional<forcing::ForcingModel> panel_model;
  std::filesystem::path panel_model_file;
  out.push_back(timed<forcing::ForcingModel>("default forcing model", [&] {
    auto model = default_forcing_model(options);
    panel_model = model.value, panel_model_file = model.file;
    return model;
  }));
  out.push_back(
      timed<forcing::ForcingModel>("default forcing model at the template's resolution", [&] {
        return default_forcing_model(options, ForcingResolution{0, 0.0});
      }));
  out.push_back(timed<StylusModes>("bundled stylus modes",
                                   [&] { return stylus_modes(options.stylus_design); }));

  // The grid as the panel's Design view asks for it: the template's resolution, the panel's model.
  out.push_back(timed<DesignResponseGrid>("design grid", [&] {
    forcing::ForcingInputOptions inputs_options;
    inputs_options.catalog = options.catalog;
    inputs_options.design_template = options.stylus_design;
    inputs_options.materials = options.materials;
    const auto inputs =
        load_prediction_inputs(inputs_options, panel_model_file, std::move(panel_model));
    const GridAxes axes = default_grid_axes(*inputs, "vero", "DM85");
    Cached<DesignResponseGrid> grid;
    grid.file = design_grid_cache_file(design_grid_cache_key(*inputs, axes));
    const auto shipped = io::shipped_twin(grid.file);
    grid.computed = !std::filesystem::exists(grid.file) && shipped.empty();
    if (!shipped.empty() && !std::filesystem::exists(grid.file)) grid.file = shipped;
    grid.value =
        cached_design_response_grid(*inputs, axes, options.progress, options.stop, options.threads);
    return grid;
  }));
  return out;
}

}  // namespace nibrig::model::design
