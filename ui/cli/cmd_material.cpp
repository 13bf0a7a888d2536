// `nibrig material calibrate bar|ringdown` and `nibrig material list`: a lab's material calibrated
// from prints (issue 47, step 1). The work is the library's: rig/calibration_bar_files (the bar's
// print files and instructions), rig/calibration_bar_fit (the ring-down fit and its uncertainty),
// model/mechanics/lab_materials (the lab's table). This file holds the options and the printing.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "model/io/bundled_assets.hpp"
#include "model/mechanics/lab_materials.hpp"
#include "rig/calibration_bar_files.hpp"
#include "rig/calibration_bar_fit.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/mechanics_figures.hpp"
#include "ui/cli/mechanics_report.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/stylus_report.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {
namespace {

namespace mech = model::mechanics;

struct CalibrationBarOptions {
  std::string material, printer;
  std::filesystem::path output, materials;
  double length = 0.0;  // 0: the paper's
};

struct RingDownSaveOptions {
  std::filesystem::path trace, bar, materials, output, plots;
  std::string name;
  bool calibrated = false, replace = false, no_plots = false;
};

mech::MaterialTable material_table_option(const std::filesystem::path& materials) {
  return mech::read_material_table(materials.empty() ? model::io::default_materials() : materials);
}

void write_bar(const CalibrationBarOptions& o) {
  const auto printer = printer_option(o.printer);
  const mech::MaterialTable materials = material_table_option(o.materials);
  const rig::CalibrationBar bar = rig::calibration_bar_of(
      o.material, materials, o.length > 0 ? std::optional<double>(o.length) : std::nullopt);
  const auto written = rig::write_calibration_bar(o.output, bar, *printer, materials);
  const auto& g = bar.geometry;
  std::printf("calibration bar: %g x %g x %g mm of %s, %.0f mm3 solid, on %s\n", g.length * 1e3,
              g.width * 1e3, g.thickness * 1e3, bar.material.c_str(), written.volume_m3 * 1e9,
              printer->name.c_str());
  std::printf("print: %s\n", written.record["printer"]["settings"].get<std::string>().c_str());
  const auto sensor = rig::bar_sensor_on_print(bar);
  std::printf(
      "clamp the first %g mm; accelerometer at %g mm from the square end; pull the round "
      "end %g mm aside and let go\n",
      g.clamp_length * 1e3, sensor.x() * 1e3, bar.preload * 1e3);
  const auto& f = written.files;
  for (const auto& file : {f.three_mf, f.stl, f.ini, f.drawing, f.instructions, f.record})
    if (!file.empty()) say_wrote(file);
  std::printf(
      "next: print it, record its ring-down as %s says, then\n"
      "  nibrig material calibrate ringdown TRACE --bar %s --name %s-lab\n",
      f.instructions.filename().string().c_str(), o.output.string().c_str(), bar.material.c_str());
}

// What makes the material's forcing curve once its modulus and damping are known: two printed tips
// captured on the rig, then the curve fitted against a forcing model (step 3 of `material
// calibrate`'s footer).
void say_next_after_ring_down(const std::string& name, const std::string& printer) {
  const std::string on = printer.empty() ? "PRINTER" : printer;
  const char* n = name.c_str();
  std::printf(
      "next: print two calibration styli of %s and capture each on the rig on your surfaces\n"
      "  nibrig export %s,tip=1mm --printer %s -o styli/%s-1mm.3mf   (and tip=4mm)\n"
      "  nibrig rig capture --usb --tool %s-1mm --surface office -o sessions/%s-1mm_office\n"
      "  nibrig catalog build sessions -o lab_catalog.json\n"
      "  nibrig forcing calibrate-material lab_catalog.json --material %s --forcing FORCING.json "
      "--save %s\n"
      "(FORCING.json: `nibrig forcing fit -o FORCING.json`, the model of the bundled catalog)\n",
      n, n, on.c_str(), n, n, n, n, n);
}

void fit_bar(const RingDownSaveOptions& o) {
  const auto saved =
      rig::calibrate_and_save_bar(o.bar, o.trace, o.name, o.materials, o.calibrated, o.replace);
  const auto& result = saved.result;
  const auto& fit = result.fit;
  const auto& u = result.uncertainty;
  std::printf("Young's modulus     %.4g +- %.2g GPa (one standard deviation)\n",
              fit.youngs_modulus / 1e9, u.youngs_modulus_sd / 1e9);
  std::printf("Rayleigh stiffness  %.4g +- %.2g s (mass term held at %.4g 1/s)\n",
              fit.rayleigh_stiffness, u.rayleigh_stiffness_sd,
              result.material.damping ? result.material.damping->mass : 0.0);
  std::printf("first mode          %.4f Hz, damping ratio %.5f\n", fit.first_mode_hz,
              fit.first_mode_damping_ratio);
  std::printf(
      "residual            %.2f %% of the trace's RMS; lag-one correlation %.2f "
      "(variances widened %.2fx for it)\n",
      100 * fit.relative_residual, u.residual_correlation, u.variance_inflation);
  std::printf("saved '%s' among the lab's materials (basis fitted)\n", o.name.c_str());
  say_wrote(saved.saved);
  say_next_after_ring_down(o.name, result.calibration.value("printer", std::string()));
  if (!o.output.empty()) {
    write_json_file(o.output, result.calibration);
    say_wrote(o.output);
  }
  if (!o.no_plots) {
    const auto folder = !o.plots.empty() ? o.plots
                        : !o.output.empty() && !o.output.parent_path().empty()
                            ? o.output.parent_path()
                            : std::filesystem::path(".");
    const auto png = folder / (file_stem(o.name) + "_ring_down.png");
    ensure_folder(folder);
    const auto trace = model::io::read_acceleration_trace(o.trace);
    plot_ring_down(trace.acceleration_m_s2, "measured", fit.fitted, trace.sample_rate_hz,
                   "Ring-down: " + o.name, png);
    say_wrote(png);
  }
}

void list_materials(const std::filesystem::path& materials) {
  const mech::MaterialTable table = material_table_option(materials);
  for (const auto& m : table.materials())
    std::printf("%-24s E %8.4g GPa  density %6.0f kg/m^3  %s\n", m.name.c_str(),
                m.youngs_modulus / 1e9, m.density, mech::describe_basis(m).c_str());
  for (const auto& place : table.looked_in()) std::printf("from %s\n", place.c_str());
}

}  // namespace

void add_material_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* cmd = app.add_subcommand("material", "A lab's own materials: calibrate from prints, list");
  cmd->require_subcommand(1);
  auto* calibrate = cmd->add_subcommand("calibrate", "Calibrate a material from printed bars");
  calibrate->require_subcommand(1);
  calibrate->footer(
      "1. `material calibrate bar --material PLA --printer prusa-mk3s -o bar/` writes the\n"
      "   ring-down bar of the paper's Sec. 5.1 (3MF, STL, slicer .ini, drawing) and how to "
      "clamp,\n"
      "   instrument and pluck it (calibration_bar.md).\n"
      "2. `material calibrate ringdown TRACE.csv --bar bar/ --name my-pla` fits its ring-down for\n"
      "   Young's modulus and Rayleigh damping with their uncertainty and saves my-pla among the\n"
      "   lab's materials (" +
      mech::lab_materials_folder().string() +
      ", or $NIBRIG_MATERIALS),\n"
      "   beside the bundled table, never over it; predict, design and export then find it by "
      "name.\n"
      "3. Its forcing curve: print it whole with two tips (`export my-pla,tip=1mm` and 4mm, with\n"
      "   --printer), capture each on the rig on your surfaces as tools my-pla-1mm and "
      "my-pla-4mm,\n"
      "   build a catalog of the sessions (`catalog build`) and `forcing calibrate-material` it\n"
      "   against a forcing model with --save: `--forcing NAME` then predicts with it. Each step\n"
      "   says the next one's command.");

  auto bar = std::make_shared<CalibrationBarOptions>();
  auto* bar_cmd =
      calibrate->add_subcommand("bar", "Write the calibration bar's print files and instructions");
  bar_cmd
      ->add_option("--material", bar->material,
                   "The material to calibrate, as the table and printer name it")
      ->required();
  bar_cmd->add_option("--printer", bar->printer, printer_option_help())->required();
  bar_cmd->add_option("-o,--output", bar->output, "Folder for the bar's files (made when new)")
      ->required();
  bar_cmd
      ->add_option("--length", bar->length,
                   "Bar length in metres (default the paper's 0.21), for a bed too small for it")
      ->check(stylus_metres("a bar length"));
  bar_cmd->add_option("--materials", bar->materials, "Material table (default: the bundled one)")
      ->check(CLI::ExistingFile);
  bar_cmd->callback([bar, global] {
    configure_logging(global->verbosity);
    write_bar(*bar);
  });

  auto fit = std::make_shared<RingDownSaveOptions>();
  auto* fit_cmd = calibrate->add_subcommand(
      "ringdown", "Fit a printed bar's ring-down and save the material by name");
  fit_cmd
      ->add_option("trace", fit->trace,
                   "The accelerometer's trace: a mono WAV from an audio input, CSV "
                   "time_s,acceleration_m_s2, or a session folder")
      ->required();
  fit_cmd->add_option("--bar", fit->bar, "The bar's folder (or its calibration_bar.json)")
      ->required();
  fit_cmd->add_option("--name", fit->name, "Name to save the fitted material under")->required();
  fit_cmd->add_flag("--calibrated", fit->calibrated,
                    "The trace is m/s^2 along the sensor axis: do not fit a gain");
  fit_cmd->add_flag("--replace", fit->replace, "Replace a lab material of that name");
  fit_cmd->add_option("--materials", fit->materials, "Material table (default: the bundled one)")
      ->check(CLI::ExistingFile);
  fit_cmd->add_option("-o,--output", fit->output, "Also write the fit and its provenance as JSON")
      ->check(file_to_write());
  fit_cmd->add_option("--plots", fit->plots, "Folder for the PNG (default: beside -o, or .)");
  fit_cmd->add_flag("--no-plots", fit->no_plots, "Do not write the PNG");
  fit_cmd->callback([fit, global] {
    configure_logging(global->verbosity);
    fit_bar(*fit);
  });

  auto list_table = std::make_shared<std::filesystem::path>();
  auto* list_cmd =
      cmd->add_subcommand("list", "The materials a name finds: the table's, then the lab's");
  list_cmd->add_option("--materials", *list_table, "Material table (default: the bundled one)")
      ->check(CLI::ExistingFile);
  list_cmd->callback([list_table, global] {
    configure_logging(global->verbosity);
    list_materials(*list_table);
  });
}

}  // namespace nibrig::ui::cli
