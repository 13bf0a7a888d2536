#include "model/design/default_forcing.hpp"

#include "model/forcing/forcing_file.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/mechanics/lab_materials.hpp"

namespace nibrig::model::design {

forcing::ForcingInputOptions default_forcing_inputs(const DefaultsOptions& o,
                                                    const ForcingResolution& resolution) {
  forcing::ForcingInputOptions in;
  in.catalog = o.catalog;
  in.design_template = o.stylus_design;
  in.materials = o.materials;
  in.modes = resolution.modes;
  in.mesh_size = resolution.mesh_size;
  return in;
}

io::CacheKey default_forcing_key(const DefaultsOptions& o, const ForcingResolution& resolution) {
  io::CacheKey key;
  key.add("nibrig default forcing").add(std::int64_t{kDefaultForcingVersion});
  key.add_file(io::or_default(o.catalog, io::default_catalog));
  key.add_file(io::or_default(o.stylus_design, io::default_stylus_design));
  key.add_file(io::or_default(o.materials, io::default_materials));
  key.add_file(io::default_threshold_curve());
  mechanics::add_lab_materials(key);
  key.add(std::int64_t{resolution.modes}).add(resolution.mesh_size);
  return key;
}

Cached<forcing::ForcingModel> default_forcing_model(const DefaultsOptions& o,
                                                    const ForcingResolution& resolution,
                                                    const forcing::DesignProgress& each_design) {
  const auto dir = o.cache_dir.empty() ? io::user_cache_dir() : o.cache_dir;
  const auto file = cache_file(dir, "default_forcing", default_forcing_key(o, resolution));
  return cached_default<forcing::ForcingModel>(
      file, "default forcing model",
      [](const std::filesystem::path& f) { return forcing::read_forcing_model(f); },
      [&] {
        const std::string designs = "designs simulated";
        if (o.progress) o.progress(designs, 0, 0);
        numeric::throw_if_cancelled(o.stop, "forcing model");
        // Designs are solved one after another on this thread, so a cancel thrown here stops the
        // next mesh from starting.
        const forcing::ForcingInputs inputs = forcing::load_forcing_inputs(
            default_forcing_inputs(o, resolution),
            [&](const forcing::DesignResponse& design, std::size_t done, std::size_t total) {
              if (o.progress) o.progress(designs, done, total);
              if (each_design) each_design(design, done, total);
              numeric::throw_if_cancelled(o.stop, "forcing model");
            });
        const auto fit_progress = numeric::step_progress(o.progress, "forcing fit", 1);
        forcing::ForcingModel model = forcing::fit_forcing_for_prediction(inputs).model;
        if (fit_progress) fit_progress(1, 1);
        numeric::throw_if_cancelled(o.stop, "forcing model");
        return model;
      },
      [](const std::filesystem::path& f, const forcing::ForcingModel& m) {
        forcing::write_forcing_model(f, m);
      });
}

}  // namespace nibrig::model::design
