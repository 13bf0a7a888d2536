#include "rig/printed_parts_files.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "model/design/stylus_export.hpp"
#include "model/io/atomic_file.hpp"
#include "model/mechanics/region_surface.hpp"
#include "model/mesh_io/stl_writer.hpp"
#include "model/mesh_io/stylus_3mf.hpp"
#include "rig/printed_parts_drawing.hpp"

namespace nibrig::rig {
namespace {

// PrusaSlicer's command line prints on a 200 × 200 mm bed unless a printer profile says otherwise,
// as the stylus's 3MF assumes (model/design/stylus_export.cpp).
constexpr double kPartsBedM = 0.200;

struct PartBox {
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};

PartBox surface_box(const model::io::SurfaceMesh& s) {
  PartBox b;
  for (const auto& v : s.vertices)
    for (std::size_t k = 0; k < 3; ++k)
      b.lo[k] = std::min(b.lo[k], v[k]), b.hi[k] = std::max(b.hi[k], v[k]);
  return b;
}

// Centred on the bed, standing on it.
std::array<double, 3> bed_placement(const PartBox& b) {
  return {kPartsBedM / 2 - (b.lo[0] + b.hi[0]) / 2, kPartsBedM / 2 - (b.lo[1] + b.hi[1]) / 2,
          -b.lo[2]};
}

std::string settings_summary(const PrintSettings& s) {
  std::ostringstream out;
  out << s.material << ", " << s.perimeters << " perimeters, " << s.fill_percent << " % "
      << s.fill_pattern << " infill, " << s.layer_height * 1e3 << " mm layers, no supports; lies "
      << s.orientation;
  return out.str();
}

}  // namespace

MeshedPart mesh_printed_part(const PrintedPart& part, const model::mechanics::CsgMeshing& meshing) {
  return {part, model::mechanics::csg_surface(part.solid, part.name, meshing)};
}

std::string prusa_slicer_ini(const PrintedPart& part) {
  const PrintSettings& s = part.settings;
  std::ostringstream out;
  out << "# nibrig rig part " << part.name << ": " << part.title << "\n"
      << "# " << settings_summary(s) << "\n"
      << "# Load it with the part: prusa-slicer --load " << part.name << ".ini " << part.name
      << ".3mf\n";
  // Keys as PrusaSlicer 2.5 names them in its .ini and in a 3MF's Metadata/Slic3r_PE.config.
  out << "layer_height = " << s.layer_height * 1e3 << "\n"
      << "first_layer_height = " << s.layer_height * 1e3 << "\n"
      << "perimeters = " << s.perimeters << "\n"
      << "top_solid_layers = " << s.top_layers << "\n"
      << "bottom_solid_layers = " << s.bottom_layers << "\n"
      << "fill_density = " << s.fill_percent << "%\n"
      << "fill_pattern = " << s.fill_pattern << "\n"
      << "support_material = 0\n"
      // The first layers squash outward; pulling them in keeps a seat or hole on the bed its size.
      << "elefant_foot_compensation = 0.2\n"
      << "filament_type = " << s.material << "\n"
      << "temperature = " << s.nozzle_temperature_C << "\n"
      << "first_layer_temperature = " << s.nozzle_temperature_C << "\n"
      << "bed_temperature = " << s.bed_temperature_C << "\n"
      << "first_layer_bed_temperature = " << s.bed_temperature_C << "\n"
      << "bed_shape = 0x0," << kPartsBedM * 1e3 << "x0," << kPartsBedM * 1e3 << "x"
      << kPartsBedM * 1e3 << ",0x" << kPartsBedM * 1e3 << "\n";
  return out.str();
}

RigPartFiles rig_part_files(const std::filesystem::path& folder, const PrintedPart& part) {
  return {folder / (part.name + ".3mf"), folder / (part.name + ".stl"),
          folder / (part.name + ".ini"), folder / (part.name + ".svg")};
}

nlohmann::json rig_parts_recipe_json(const std::vector<MeshedPart>& parts,
                                     const std::vector<RigPartFiles>& files,
                                     const RigPartDimensions& d) {
  if (parts.size() != files.size())
    throw std::invalid_argument("rig parts recipe: a file set per part is needed");
  nlohmann::json j;
  j["kind"] = "rig_parts";
  j["rig"] = {{"pivot_height_mm", pivot_height(d) * 1e3},
              {"post_extrusion_length_mm", post_extrusion_length(d) * 1e3},
              {"post_rim_clearance_mm", post_rim_clearance(d) * 1e3}};
  j["parts"] = nlohmann::json::array();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto& p = parts[i].part;
    const auto& s = p.settings;
    const PartBox box = surface_box(parts[i].surface);
    const auto place = bed_placement(box);
    nlohmann::json r;
    r["name"] = p.name;
    r["title"] = p.title;
    r["purpose"] = p.purpose;
    r["material"] = s.material;
    r["volume_mm3"] = model::mechanics::enclosed_volume(parts[i].surface) * 1e9;
    r["triangles"] = parts[i].surface.triangles.size();
    for (std::size_t k = 0; k < 3; ++k) {
      r["bed_box_mm"]["min"].push_back((box.lo[k] + place[k]) * 1e3);
      r["bed_box_mm"]["max"].push_back((box.hi[k] + place[k]) * 1e3);
    }
    r["settings"] = {{"layer_height_mm", s.layer_height * 1e3},
                     {"perimeters", s.perimeters},
                     {"top_layers", s.top_layers},
                     {"bottom_layers", s.bottom_layers},
                     {"fill_percent", s.fill_percent},
                     {"fill_pattern", s.fill_pattern},
                     {"supports", false},
                     {"nozzle_C", s.nozzle_temperature_C},
                     {"bed_C", s.bed_temperature_C}};
    r["orientation"] = s.orientation;
    r["dimensions_mm"] = nlohmann::json::object();
    for (const auto& dim : p.dimensions) r["dimensions_mm"][dim.label] = dim.value * 1e3;
    r["hardware"] = p.hardware;
    r["files"] = {{"three_mf", files[i].three_mf.filename().string()},
                  {"stl", files[i].stl.filename().string()},
                  {"ini", files[i].ini.filename().string()},
                  {"drawing", files[i].drawing.filename().string()}};
    j["parts"].push_back(r);
  }
  return j;
}

RigPartsWritten write_rig_parts(const std::filesystem::path& folder, const RigPartDimensions& d,
                                const model::mechanics::CsgMeshing& meshing) {
  const auto where = folder.empty() ? std::filesystem::path(".") : folder;
  model::design::check_stylus_folder(where);
  // Every part meshed before the first file is written: a part that cannot be made leaves the
  // folder as it was.
  std::vector<MeshedPart> meshed;
  for (const auto& part : rig_printed_parts(d)) meshed.push_back(mesh_printed_part(part, meshing));
  std::filesystem::create_directories(where);
  RigPartsWritten written;
  for (const auto& m : meshed) {
    const RigPartFiles files = rig_part_files(where, m.part);
    const PartBox box = surface_box(m.surface);
    for (std::size_t k = 0; k < 2; ++k)
      if (box.hi[k] - box.lo[k] > kPartsBedM)
        throw std::runtime_error(files.three_mf.string() +
                                 ": the part is wider than the 200 mm bed");
    model::mesh_io::ThreeMfPart three_mf;
    three_mf.name = "nibrig rig " + m.part.title;
    three_mf.placement_m = bed_placement(box);
    three_mf.metadata = {
        {"Title", three_mf.name},
        {"Application", "nibrig"},
        {"Description", m.part.purpose + ". Print: " + settings_summary(m.part.settings) + " (" +
                            files.ini.filename().string() + ")"}};
    three_mf.regions.push_back({m.surface, m.part.settings.material, {230, 120, 40}});
    model::mesh_io::write_3mf(files.three_mf, three_mf);
    model::mesh_io::write_binary_stl(files.stl, m.surface);
    model::io::write_file_atomically(files.ini, prusa_slicer_ini(m.part));
    model::io::write_file_atomically(files.drawing, part_drawing_svg(m.part));
    written.parts.push_back(files);
  }
  written.recipe = where / "rig_parts.json";
  written.recipe_json = rig_parts_recipe_json(meshed, written.parts, d);
  model::io::write_file_atomically(written.recipe, written.recipe_json.dump(2) + "\n");
  return written;
}

}  // namespace nibrig::rig
