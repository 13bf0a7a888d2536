#include "model/design/stylus_modes.hpp"

#include <spdlog/spdlog.h>

#include <nlohmann/json.hpp>
#include <numbers>

#include "model/io/atomic_file.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/finite_output.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/lab_materials.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "model/modal/modal_model_checks.hpp"

namespace nibrig::model::design {
namespace {

namespace jf = io::json_fields;
constexpr const char* kStylusModesFormat = "nibrig-stylus-modes";

StylusModes read_stylus_modes(const std::filesystem::path& file) {
  const nlohmann::json root = jf::parse_file(file);
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, kStylusModesFormat, kStylusModesVersion);
  const auto numbers = [&](const std::string& key) {
    return jf::as_number_array(jf::member(root, key, file, ""), file, key);
  };
  StylusModes modes{jf::string_member(root, "design", file, ""),
                    {numbers("omega_rad_s"), numbers("zeta"), numbers("input"), numbers("output")}};
  try {
    modal::check_modal_model(modes.modal, "the cached stylus modes");
  } catch (const std::invalid_argument& e) {
    throw io::FormatError(file, "", e.what());
  }
  return modes;
}

void write_stylus_modes(const std::filesystem::path& file, const StylusModes& modes) {
  const nlohmann::json out = {{"format", kStylusModesFormat}, {"version", kStylusModesVersion},
                              {"design", modes.design_name},  {"omega_rad_s", modes.modal.omega},
                              {"zeta", modes.modal.zeta},     {"input", modes.modal.input},
                              {"output", modes.modal.output}};
  // dump() writes each double with the digits that read back to the same double.
  io::write_file_atomically(file, io::json_text(out, file, -1));
}

}  // namespace

std::filesystem::path stylus_modes_file(const std::filesystem::path& design_file,
                                        const std::filesystem::path& cache_dir) {
  io::CacheKey key;
  key.add("nibrig stylus modes").add(std::int64_t{kStylusModesVersion});
  key.add_file(io::or_default(design_file, io::default_stylus_design))
      .add_file(io::default_materials());
  mechanics::add_lab_materials(key);
  return cache_file(cache_dir.empty() ? io::user_cache_dir() : cache_dir, "stylus_modes", key);
}

Cached<StylusModes> stylus_modes(const std::filesystem::path& design_file,
                                 const std::filesystem::path& cache_dir) {
  const auto design = io::or_default(design_file, io::default_stylus_design);
  const auto materials_file = io::default_materials();
  return cached_default<StylusModes>(
      stylus_modes_file(design_file, cache_dir), "stylus modes", read_stylus_modes,
      [&] {
        const auto materials = mechanics::read_material_table(materials_file);
        const mechanics::Design d = mechanics::read_design(design, materials);
        const mechanics::DesignModel model = mechanics::build_design_model(d, materials);
        spdlog::info("{}: {} modes, first at {:.1f} Hz (meshing and modes {:.2f} s)", d.name,
                     model.modal.size(), model.modal.omega.front() / (2 * std::numbers::pi),
                     model.seconds.meshing_s + model.seconds.assembly_s + model.seconds.modes_s);
        return StylusModes{d.name, model.modal};
      },
      write_stylus_modes);
}

}  // namespace nibrig::model::design
