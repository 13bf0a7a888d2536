#include "model/design/stylus_export.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "model/design/printability.hpp"
#include "model/design/slicer_settings.hpp"
#include "model/forcing/printed_tool_design.hpp"
#include "model/io/atomic_file.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/mechanics/region_surface.hpp"
#include "model/mesh_io/stl_writer.hpp"
#include "model/mesh_io/stylus_3mf.hpp"

namespace nibrig::model::design {
namespace {

// PrusaSlicer's command line prints on a 200 × 200 mm bed unless a printer profile says otherwise.
constexpr double kBedCentreM = 0.100;

std::array<std::uint8_t, 3> display_colour(const StylusRegion& region) {
  // Clear VeroClear, the soft Digital Materials darker the softer: what the prints look like.
  double soft = 0.0;
  for (const auto& share : region.mix)
    soft += share.fraction * (share.material == "DM85"   ? 1.0
                              : share.material == "DM95" ? 0.6
                                                         : 0.0);
  const auto level = static_cast<std::uint8_t>(std::lround(220 - 160 * soft));
  return {level, level, static_cast<std::uint8_t>(std::min(255.0, level + 20.0))};
}

// Stood on its back end (the stylus's +x becomes +z), a proper rotation: the triangles keep their
// outward winding.
io::SurfaceMesh stood_up(io::SurfaceMesh surface) {
  for (auto& v : surface.vertices) v = {-v[2], v[1], v[0]};
  return surface;
}

}  // namespace

StylusPrint stylus_print(const PredictionSetup& setup, const DesignPoint& point) {
  MixedDesign mixed = [&] {
    try {
      return solved_design(setup, point);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("design " + label(point) + ": " + e.what());
    }
  }();
  const mechanics::TetMesh mesh = mechanics::mesh_design(mixed.design);
  StylusPrint print;
  print.point = point;
  print.design_name = mixed.design.name;
  for (auto& surface : mechanics::region_surfaces(mesh)) {
    StylusRegion region;
    region.material = mechanics::material_of_region(mixed.design, surface.name);
    region.surface = std::move(surface);
    const bool is_mix =
        std::none_of(setup.materials.materials().begin(), setup.materials.materials().end(),
                     [&](const auto& m) { return m.name == region.material; });
    if (is_mix)
      region.mix = point.mix;
    else
      region.mix = {{catalog_material_name(region.material), 1.0}};
    print.regions.push_back(std::move(region));
  }
  print.design = std::move(mixed.design);
  print.materials = std::move(mixed.materials);
  return print;
}

StylusPrint stylus_print(const forcing::ForcingInputOptions& inputs, const DesignPoint& point) {
  PredictionSetup setup;
  setup.materials =
      mechanics::read_material_table(io::or_default(inputs.materials, io::default_materials));
  setup.template_design = mechanics::read_design(
      io::or_default(inputs.design_template, io::default_stylus_design), setup.materials);
  setup.mesh_size = inputs.mesh_size;
  setup.modes = inputs.modes;
  return stylus_print(setup, point);
}

std::string printer_material(const StylusRegion& region) {
  if (region.mix.size() == 1) return region.material;
  std::string out;
  for (const auto& share : region.mix) {
    char part[64];
    std::snprintf(part, sizeof part, "%s%s %.0f %%", out.empty() ? "" : " + ",
                  share.material.c_str(), 100.0 * share.fraction);
    out += part;
  }
  return out + " (digital material)";
}

StylusFiles stylus_files(const std::filesystem::path& three_mf, const StylusPrint& print) {
  StylusFiles files{
      three_mf, {}, three_mf.parent_path() / (three_mf.stem().string() + ".json"), {}};
  if (print.printer && reads_prusa_slicer(*print.printer))
    files.slicer_config = three_mf.parent_path() / (three_mf.stem().string() + ".ini");
  for (const auto& region : print.regions)
    files.stls.push_back(three_mf.parent_path() /
                         (three_mf.stem().string() + "-" + region.surface.name + ".stl"));
  return files;
}

nlohmann::json stylus_recipe_json(const StylusPrint& print, const StylusFiles& files) {
  nlohmann::json j;
  j["kind"] = "stylus_recipe";
  j["design"] = to_string(print.point);
  j["design_name"] = print.design_name;
  j["mesh_size_mm"] = print.design.mesh_size * 1e3;
  j["regions"] = nlohmann::json::array();
  for (const auto& region : print.regions) {
    nlohmann::json r;
    r["name"] = region.surface.name;
    r["material"] = region.material;
    r["printer_material"] = printer_material(region);
    for (const auto& m : print.materials.materials())
      if (m.name == region.material) r["material_basis"] = m.basis.empty() ? "unstated" : m.basis;
    r["mix"] = nlohmann::json::array();
    for (const auto& share : region.mix)
      r["mix"].push_back({{"material", share.material}, {"fraction", share.fraction}});
    r["triangles"] = region.surface.triangles.size();
    r["volume_mm3"] = mechanics::enclosed_volume(region.surface) * 1e9;
    j["regions"].push_back(r);
  }
  j["substitutes"] = nlohmann::json::array();
  for (const auto& s : print.substitutes) {
    nlohmann::json sub{{"design", to_string(s.point)}, {"cost", s.cost}, {"cost_sd", s.cost_sd}};
    if (s.to_target) sub["to_target"] = *s.to_target, sub["to_target_sd"] = s.to_target_sd;
    if (!s.outside_constraints.empty()) sub["outside_constraints"] = s.outside_constraints;
    j["substitutes"].push_back(sub);
  }
  j["files"]["three_mf"] = files.three_mf.filename().string();
  for (const auto& stl : files.stls) j["files"]["stls"].push_back(stl.filename().string());
  if (!files.slicer_config.empty())
    j["files"]["slicer_config"] = files.slicer_config.filename().string();
  if (print.printer) {
    const auto& p = *print.printer;
    nlohmann::json printer{{"name", p.name},
                           {"printer", p.printer},
                           {"process", io::process_name(p.process)},
                           {"orientation", p.orientation},
                           {"orientation_reason", p.orientation_reason},
                           {"supports", p.supports},
                           {"post_process", p.post_process},
                           {"slicer", p.slicer},
                           {"layer_height_mm", p.layer_height_m * 1e3},
                           {"smallest_tip_mm", smallest_tip_m(p) * 1e3},
                           {"profile", p.file.string()}};
    if (p.process == io::PrintProcess::fdm)
      printer["nozzle_diameter_mm"] = p.nozzle_diameter_m * 1e3;
    if (p.process == io::PrintProcess::msla) printer["pixel_size_mm"] = p.pixel_size_m() * 1e3;
    if (p.process == io::PrintProcess::polyjet)
      printer["xy_resolution_mm"] = p.xy_resolution_m * 1e3;
    printer["slicer_settings"] = nlohmann::json::object();
    for (const auto& [k, v] : prusa_slicer_settings(p)) printer["slicer_settings"][k] = v;
    printer["sources"] = nlohmann::json::object();
    for (const auto& [k, v] : p.sources) printer["sources"][k] = v;
    if (!files.slicer_config.empty())
      printer["slice_command"] =
          prusa_slicer_command(p, files.slicer_config.filename(), files.three_mf.filename());
    j["printer"] = printer;
  }
  return j;
}

void check_stylus_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::path existing = folder.empty() ? std::filesystem::path(".") : folder;
  while (!std::filesystem::exists(existing, error) && existing != ".")
    existing = existing.has_parent_path() && existing != existing.parent_path()
                   ? existing.parent_path()
                   : std::filesystem::path(".");
  if (!std::filesystem::is_directory(existing, error))
    throw std::runtime_error(folder.string() + ": " + existing.string() +
                             " is not a folder to write the files into");
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error(folder.string() + ": " +
                             (existing == folder ? std::string("this folder") : existing.string()) +
                             " cannot be written (" + std::strerror(errno) + ")");
}

void check_stylus_outputs(const std::filesystem::path& three_mf) {
  check_stylus_folder(three_mf.parent_path().empty() ? std::filesystem::path(".")
                                                     : three_mf.parent_path());
  const auto recipe = stylus_files(three_mf, StylusPrint{}).recipe;
  const auto ini = three_mf.parent_path() / (three_mf.stem().string() + ".ini");
  io::refuse_companion_link(recipe, three_mf);
  io::refuse_companion_link(ini, three_mf);
  for (const auto& file : {three_mf, recipe, ini}) io::output_target(file);
}

StylusFiles write_stylus_files(const std::filesystem::path& three_mf, const StylusPrint& print) {
  if (print.printer) check_printable(*print.printer, print);
  const auto folder =
      three_mf.parent_path().empty() ? std::filesystem::path(".") : three_mf.parent_path();
  check_stylus_folder(folder);
  std::filesystem::create_directories(folder);
  const StylusFiles files = stylus_files(three_mf, print);
  for (const auto& stl : files.stls) io::refuse_companion_link(stl, three_mf);
  io::refuse_companion_link(files.recipe, three_mf);
  if (!files.slicer_config.empty()) io::refuse_companion_link(files.slicer_config, three_mf);

  // As the printer orients it (lying along x without one), on the bed (lowest point at z = 0),
  // centred on it.
  const bool standing = print.printer && print.printer->orientation == "standing";
  std::vector<io::SurfaceMesh> oriented;
  for (const auto& region : print.regions)
    oriented.push_back(standing ? stood_up(region.surface) : region.surface);
  const double centre_x = print.printer ? 0.5 * print.printer->build_volume_m[0] : kBedCentreM;
  const double centre_y = print.printer ? 0.5 * print.printer->build_volume_m[1] : kBedCentreM;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const auto& surface : oriented)
    for (const auto& v : surface.vertices)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], v[static_cast<std::size_t>(k)]);
        hi[k] = std::max(hi[k], v[static_cast<std::size_t>(k)]);
      }
  mesh_io::ThreeMfPart part;
  part.name = "nibrig stylus " + to_string(print.point);
  part.placement_m = {centre_x - 0.5 * (lo[0] + hi[0]), centre_y - 0.5 * (lo[1] + hi[1]), -lo[2]};
  part.metadata = {
      {"Title", part.name},
      {"Application", "nibrig"},
      {"Description", "design " + to_string(print.point) + " (" + print.design_name +
                          "), meshed at " + std::to_string(1e3 * print.design.mesh_size) + " mm"}};
  for (std::size_t i = 0; i < print.regions.size(); ++i)
    part.regions.push_back(
        {oriented[i], printer_material(print.regions[i]), display_colour(print.regions[i])});
  const SlicerSettings settings =
      print.printer ? prusa_slicer_settings(*print.printer) : SlicerSettings{};
  if (!settings.empty()) {
    part.attachments.emplace_back("Metadata/Slic3r_PE.config", prusa_slicer_3mf_config(settings));
  }
  mesh_io::write_3mf(files.three_mf, part);
  for (std::size_t i = 0; i < print.regions.size(); ++i)
    mesh_io::write_binary_stl(files.stls[i], oriented[i]);
  if (!files.slicer_config.empty())
    io::write_file_atomically(files.slicer_config, prusa_slicer_ini(settings));
  io::write_file_atomically(files.recipe, stylus_recipe_json(print, files).dump(2) + "\n");
  return files;
}

}  // namespace nibrig::model::design
