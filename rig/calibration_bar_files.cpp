#include "rig/calibration_bar_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/design/printability.hpp"
#include "model/design/slicer_settings.hpp"
#include "model/design/stylus_export.hpp"
#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/mechanics/beam_theory.hpp"
#include "model/mechanics/region_surface.hpp"
#include "model/mesh_io/stl_writer.hpp"
#include "model/mesh_io/stylus_3mf.hpp"
#include "rig/printed_parts_drawing.hpp"
#include "rig/printed_parts_files.hpp"

namespace nibrig::rig {
namespace {

namespace jf = model::io::json_fields;
namespace mech = model::mechanics;

constexpr const char* kBarRecord = "calibration_bar.json";

// What a bar record says of its geometry, in millimetres as every recipe does.
nlohmann::json bar_geometry_json(const mech::BarGeometry& g) {
  return {{"length_mm", g.length * 1e3},
          {"width_mm", g.width * 1e3},
          {"thickness_mm", g.thickness * 1e3},
          {"clamp_length_mm", g.clamp_length * 1e3},
          {"end_radius_mm", g.end_radius * 1e3},
          {"cutout", g.cutout},
          {"cutout_radius_mm", g.cutout_radius * 1e3},
          {"cutout_offset_mm", g.cutout_offset * 1e3}};
}

nlohmann::json point_mm(const Eigen::Vector3d& p) {
  return {p.x() * 1e3, p.y() * 1e3, p.z() * 1e3};
}

}  // namespace

CalibrationBarFiles calibration_bar_files(const std::filesystem::path& folder,
                                          const model::io::PrinterProfile& printer) {
  CalibrationBarFiles f;
  f.three_mf = folder / "calibration_bar.3mf";
  f.stl = folder / "calibration_bar.stl";
  if (model::design::reads_prusa_slicer(printer)) f.ini = folder / "calibration_bar.ini";
  f.drawing = folder / "calibration_bar.svg";
  f.instructions = folder / "calibration_bar.md";
  f.record = folder / kBarRecord;
  return f;
}

std::string calibration_bar_instructions(const CalibrationBar& bar,
                                         const model::io::PrinterProfile& printer,
                                         const mech::Material& material,
                                         const CalibrationBarFiles& files) {
  const mech::BarGeometry& g = bar.geometry;
  const Eigen::Vector3d sensor = bar_sensor_on_print(bar), tip = bar_tip_on_print(bar);
  // The table's values predict where the first mode will be: the recording must resolve it.
  const double f1 = mech::cantilever_bending_frequencies(material.youngs_modulus, material.density,
                                                         g.free_length(), g.width, g.thickness, 1)
                        .front();
  const double mass = material.density * g.width * g.thickness * g.length;
  // f ∝ 1/L², so E fitted from f ∝ f² goes as L⁻⁴: a clamp misplaced by 1 mm moves E by 4/L per mm.
  const double per_mm = 4e-3 / g.free_length();
  std::string slice = printer.slicer.empty() ? "the printer's own software" : printer.slicer;
  if (!files.ini.empty())
    slice = "`" +
            model::design::prusa_slicer_command(printer, files.ini.filename(),
                                                files.three_mf.filename()) +
            "`";
  std::string out;
  out += fmt::format("# Ring-down calibration bar: {} on {}\n\n", bar.material, printer.printer);
  out += fmt::format(
      "The bar of Piovarci et al. 2018, Sec. 5.1: {:g} × {:g} × {:g} mm, the free end rounded "
      "(R{:g}){}. Its ring-down, fitted by `nibrig material calibrate ringdown`, gives {}'s "
      "Young's modulus and Rayleigh damping as printed by this printer.\n\n",
      g.length * 1e3, g.width * 1e3, g.thickness * 1e3, g.end_radius * 1e3,
      g.cutout ? fmt::format(", an R{:g} hole {:g} mm from that end", g.cutout_radius * 1e3,
                             g.cutout_offset * 1e3)
               : std::string(),
      bar.material);
  out += "## 1. Print\n\n";
  out += fmt::format("- Slice {} with {}.\n", files.three_mf.filename().string(), slice);
  out += fmt::format(
      "- The profile's settings: {}. Whatever they say of a stylus's orientation, "
      "the bar lies flat on the bed and needs no supports; its layers run along it, "
      "as a lying stylus's do.\n",
      model::design::describe_print_settings(printer));
  if (!printer.post_process.empty())
    out += "- After printing (the profile's advice for a stylus): " + printer.post_process + "\n";
  out += fmt::format(
      "- Weigh it: a solid bar of the table's density weighs {:.1f} g. Much less "
      "means it is not solid, and the fit would be of the infill, not the "
      "material.\n\n",
      mass * 1e3);
  out += "## 2. Mark, clamp, place the accelerometer\n\n";
  out += fmt::format(
      "- Mark a line across the bar {:g} mm from the square end, and the accelerometer's centre "
      "on the centre line {:g} mm from the square end ({:g} mm from the round end).\n",
      g.clamp_length * 1e3, sensor.x() * 1e3, (g.length - sensor.x()) * 1e3);
  out += fmt::format(
      "- Clamp the first {:g} mm in a vice or under a bar on a heavy table, flat side up, the "
      "clamp's edge on the line. The fit assumes a free length of {:g} mm: each millimetre off "
      "moves the fitted modulus by {:.1f} %.\n",
      g.clamp_length * 1e3, g.free_length() * 1e3, 100 * per_mm);
  out +=
      "- Glue the accelerometer (cyanoacrylate, or wax for a reusable sensor) on the mark, its "
      "measuring axis through the thickness. The fit does not model its mass: use the lightest "
      "board you have, and tape its cable to the table, not to the free bar.\n\n";
  out += "## 3. Pluck and record\n\n";
  out += fmt::format(
      "- The table's values for {} put the first bending mode near {:.1f} Hz. Record the "
      "accelerometer through an audio input (or the rig's accelerometer input) at 2 kHz or more, "
      "from before the release until the ringing has died away. An audio input's high-pass "
      "must lie well below {:.1f} Hz (a third of it at most), or it bends the first mode.\n",
      material.name, f1, f1);
  out += fmt::format(
      "- Pull the middle of the round end ({:g} mm from the square end) {:g} mm aside, along the "
      "thickness, against a ruler, and let go cleanly: slide the finger off, or cut a thread.\n",
      tip.x() * 1e3, bar.preload * 1e3);
  out +=
      "- Save the accelerometer's channel as a mono WAV, or as CSV "
      "`time_s,acceleration_m_s2` (any gain: the fit finds it).\n\n";
  out += "## 4. Fit and save\n\n";
  out += fmt::format(
      "`nibrig material calibrate ringdown TRACE.csv --bar {} --name NAME` fits the modulus and "
      "Rayleigh damping with their uncertainty and saves NAME among the lab's materials, for "
      "`predict`, `design` and `export` to use by name.\n",
      files.record.parent_path().filename().string().empty()
          ? "."
          : files.record.parent_path().filename().string());
  return out;
}

CalibrationBarWritten write_calibration_bar(const std::filesystem::path& folder,
                                            const CalibrationBar& bar,
                                            const model::io::PrinterProfile& printer,
                                            const mech::MaterialTable& materials) {
  const mech::Material& material = materials.find(bar.material);
  if (const auto reasons = calibration_bar_refusals(printer, bar); !reasons.empty()) {
    std::string message = "printer '" + printer.name + "' cannot print the calibration bar: ";
    for (std::size_t i = 0; i < reasons.size(); ++i) message += (i ? "; " : "") + reasons[i];
    throw model::design::PrintRefused(message);
  }
  const auto where = folder.empty() ? std::filesystem::path(".") : folder;
  model::design::check_stylus_folder(where);
  const PrintedPart part = calibration_bar_part(bar, printer);
  const MeshedPart meshed = mesh_printed_part(part);
  CalibrationBarWritten written;
  written.files = calibration_bar_files(where, printer);
  const CalibrationBarFiles& f = written.files;
  for (const auto& companion : {f.stl, f.ini, f.drawing, f.instructions, f.record})
    if (!companion.empty()) model::io::refuse_companion_link(companion, f.three_mf);
  written.volume_m3 = mech::enclosed_volume(meshed.surface);

  // In the middle of the printer's bed, along its longer side, lying on it.
  model::io::SurfaceMesh surface = meshed.surface;
  const bool turn = printer.build_volume_m[1] > printer.build_volume_m[0];
  if (turn)
    for (auto& v : surface.vertices) v = {-v[1], v[0], v[2]};
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& v : surface.vertices)
    for (std::size_t k = 0; k < 3; ++k)
      lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  model::mesh_io::ThreeMfPart three_mf;
  three_mf.name = "nibrig calibration bar " + bar.material;
  three_mf.placement_m = {printer.build_volume_m[0] / 2 - (lo[0] + hi[0]) / 2,
                          printer.build_volume_m[1] / 2 - (lo[1] + hi[1]) / 2, -lo[2]};
  three_mf.metadata = {
      {"Title", three_mf.name}, {"Application", "nibrig"}, {"Description", part.purpose}};
  three_mf.regions.push_back({surface, bar.material, {230, 120, 40}});
  const auto settings = model::design::prusa_slicer_settings(printer);
  if (!settings.empty())
    three_mf.attachments.emplace_back("Metadata/Slic3r_PE.config",
                                      model::design::prusa_slicer_3mf_config(settings));

  nlohmann::json& r = written.record;
  r["format"] = "nibrig-calibration-bar";
  r["version"] = 1;
  r["material"] = bar.material;
  r["material_basis"] = material.basis.empty() ? "unstated" : material.basis;
  r["bar"] = bar_geometry_json(bar.geometry);
  r["preload_mm"] = bar.preload * 1e3;
  r["sensor_mm"] = point_mm(bar_sensor_on_print(bar));
  r["tip_mm"] = point_mm(bar_tip_on_print(bar));
  r["volume_mm3"] = written.volume_m3 * 1e9;
  r["printer"] = {{"name", printer.name},
                  {"printer", printer.printer},
                  {"process", model::io::process_name(printer.process)},
                  {"settings", model::design::describe_print_settings(printer)},
                  {"profile", printer.file.string()}};
  r["files"] = {{"three_mf", f.three_mf.filename().string()},
                {"stl", f.stl.filename().string()},
                {"drawing", f.drawing.filename().string()},
                {"instructions", f.instructions.filename().string()}};
  if (!f.ini.empty()) r["files"]["slicer_config"] = f.ini.filename().string();

  std::filesystem::create_directories(where);
  model::io::OutputSet set;  // all the bar's files or none of them
  model::mesh_io::write_3mf(f.three_mf, three_mf);
  model::mesh_io::write_binary_stl(f.stl, surface);
  if (!f.ini.empty())
    model::io::write_file_atomically(f.ini, model::design::prusa_slicer_ini(settings));
  model::io::write_file_atomically(f.drawing, part_drawing_svg(part));
  model::io::write_file_atomically(f.instructions,
                                   calibration_bar_instructions(bar, printer, material, f));
  model::io::write_file_atomically(f.record, r.dump(2) + "\n");
  set.commit();
  return written;
}

CalibrationBarRecord read_calibration_bar(const std::filesystem::path& folder_or_file) {
  const auto file =
      std::filesystem::is_directory(folder_or_file) ? folder_or_file / kBarRecord : folder_or_file;
  if (!std::filesystem::exists(file))
    throw std::invalid_argument(file.string() +
                                ": no such file (expected the calibration_bar.json that `nibrig "
                                "material calibrate bar` writes)");
  const nlohmann::json root = jf::parse_file(file);
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, "nibrig-calibration-bar", 1);
  CalibrationBarRecord out;
  out.file = file;
  out.bar.material = jf::string_member(root, "material", file, "");
  out.bar.preload = jf::number_member(root, "preload_mm", file, "") * 1e-3;
  const auto& g = jf::as_object(jf::member(root, "bar", file, ""), file, "bar");
  mech::BarGeometry& b = out.bar.geometry;
  b.length = jf::number_member(g, "length_mm", file, "bar") * 1e-3;
  b.width = jf::number_member(g, "width_mm", file, "bar") * 1e-3;
  b.thickness = jf::number_member(g, "thickness_mm", file, "bar") * 1e-3;
  b.clamp_length = jf::number_member(g, "clamp_length_mm", file, "bar") * 1e-3;
  b.end_radius = jf::number_member(g, "end_radius_mm", file, "bar") * 1e-3;
  const auto& cutout = jf::member(g, "cutout", file, "bar");
  if (!cutout.is_boolean())
    throw model::io::FormatError(file, jf::place("bar.cutout"), "expected true or false");
  b.cutout = cutout.get<bool>();
  b.cutout_radius = jf::number_member(g, "cutout_radius_mm", file, "bar") * 1e-3;
  b.cutout_offset = jf::number_member(g, "cutout_offset_mm", file, "bar") * 1e-3;
  try {
    mech::validate(b);
  } catch (const std::invalid_argument& e) {
    throw model::io::FormatError(file, jf::place("bar"), e.what());
  }
  if (!(out.bar.preload > 0))
    throw model::io::FormatError(file, jf::place("preload_mm"), "expected a positive preload");
  const auto& printer = jf::as_object(jf::member(root, "printer", file, ""), file, "printer");
  out.printer = jf::string_member(printer, "name", file, "printer");
  out.printer_process = jf::string_member(printer, "process", file, "printer");
  return out;
}

}  // namespace nibrig::rig
