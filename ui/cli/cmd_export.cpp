// `nibrig export DESIGN -o stylus.3mf`: a design point (or the design of a prediction file) as the
// files a printer takes — the stylus its prediction simulated, region by region as the FEM meshed
// it, in one 3MF and an STL per region (model/design/stylus_export.hpp), with its print sheet
// (ui/figures/stylus_sheet.hpp).
#include <fmt/format.h>

#include <iostream>

#include "model/design/prediction_file.hpp"
#include "model/design/printability.hpp"
#include "model/design/slicer_settings.hpp"
#include "model/design/stylus_export.hpp"
#include "model/mechanics/region_surface.hpp"
#include "model/space/space_file.hpp"
#include "model/design/design_search.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/stylus_report.hpp"
#include "ui/figures/stylus_sheet.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {

namespace design = model::design;

std::optional<model::io::PrinterProfile> printer_option(const std::string& name_or_file) {
  if (name_or_file.empty()) return std::nullopt;
  try {
    return model::io::find_printer_profile(name_or_file);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--printer", e.what());
  }
}

std::string printer_option_help() {
  std::string names;
  for (const auto& n : model::io::bundled_printer_names()) names += (names.empty() ? "" : ", ") + n;
  return "Printer profile, a name or a file: the 3MF carries its slicer settings (100 % infill, walls, layers, "
         "orientation, supports), a .ini beside it for `prusa-slicer --load`, and a design it cannot make is refused "
         "(bundled: " + names + "; your own: " + model::io::user_printers_folder().string() + "/NAME.json)";
}

void print_stylus_files(const design::StylusPrint& print, const figures::ExportedStylus& exported) {
  std::cout << fmt::format("stylus {} ({}), meshed at {:.2f} mm:\n", design::label(print.point), print.design_name,
                           print.design.mesh_size * 1e3);
  for (const auto& region : print.regions) {
    std::string basis;
    for (const auto& m : print.materials.materials())
      if (m.name == region.material) basis = ", " + model::mechanics::describe_basis(m);
    std::cout << fmt::format("  {}: {}, {} triangles, {:.1f} mm3{}\n", region.surface.name,
                             design::printer_material(region), region.surface.triangles.size(),
                             model::mechanics::enclosed_volume(region.surface) * 1e9, basis);
  }
  if (print.printer) {
    std::cout << fmt::format("printer {}: {}\n", print.printer->name, design::describe_print_settings(*print.printer));
    if (!exported.files.slicer_config.empty())
      std::cout << "slice with: "
                << design::prusa_slicer_command(*print.printer, exported.files.slicer_config, exported.files.three_mf)
                << "\n";
  }
  say_wrote(exported.files.three_mf);
  for (const auto& stl : exported.files.stls) say_wrote(stl);
  if (!exported.files.slicer_config.empty()) say_wrote(exported.files.slicer_config);
  say_wrote(exported.files.recipe);
  say_wrote(exported.sheet);
}

namespace {

struct ExportOptions {
  std::string design;
  std::filesystem::path output = "stylus.3mf";
  model::forcing::ForcingInputOptions inputs;
  std::string surface;  // the sheet's prediction; default: a prediction file's own
  std::filesystem::path space_file;
  std::filesystem::path forcing_model;
  std::string printer;  // --printer: a profile's name or file
};

// A design point has no surface: the prediction file's is its own.
design::PredictedDesign design_to_export(const std::string& text) {
  std::error_code error;
  if (std::filesystem::is_regular_file(text, error)) return design::read_predicted_design(text);
  // A JSON file's name or a path is a file that is not there, not a design point without a tip.
  if (std::filesystem::path(text).extension() == ".json" || text.find('/') != std::string::npos)
    throw CLI::ValidationError("DESIGN", text + ": no such file (expected a prediction file, or a design "
                                                "point such as \"DM85:0.62,vero:0.38,tip=2.7mm\")");
  try {
    return {design::parse_design_point(text), {}};
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("DESIGN", std::string(e.what()) +
                                             " (expected a design point such as \"DM85:0.62,vero:0.38,tip=2.7mm\" "
                                             "or a prediction file)");
  }
}

void run_export(const ExportOptions& o) {
  if (o.output.extension() != ".3mf")
    throw CLI::ValidationError("--output", "'" + o.output.string() + "' is not a .3mf file");
  const auto [point, file_surface] = design_to_export(o.design);
  const std::string surface = o.surface.empty() ? file_surface : o.surface;
  if (!o.space_file.empty() && surface.empty())
    throw CLI::ValidationError("--space", "places the design from its prediction: give --surface too");
  std::optional<model::space::SpaceFile> space;
  if (!o.space_file.empty()) {
    space = model::space::read_space_file(o.space_file);
    if (!space->descriptor_map)
      throw std::invalid_argument(o.space_file.string() +
                                  " has no descriptor map (fit it with --descriptors): a design is "
                                  "placed from its predicted descriptors");
  }
  const auto printer = printer_option(o.printer);
  design::check_stylus_outputs(o.output);  // not onto the design or space just read, before the prediction
  if (surface.empty()) {  // the print alone: no prediction to put on the sheet
    auto print = design::stylus_print(o.inputs, point);
    print.printer = printer;
    print_stylus_files(print, figures::export_stylus(o.output, print, {}));
    return;
  }
  if (printer && !space) {  // refused before the prediction when no substitute can be offered
    auto print = design::stylus_print(o.inputs, point);
    design::check_printable(*printer, print);
  }
  if (o.forcing_model.empty() && warnings_shown())
    std::cerr << "no --forcing given: the catalog's default forcing model (fitted once, then kept in the user cache)\n";
  const auto inputs = load_prediction_inputs(o.inputs, o.forcing_model, std::nullopt, design_progress());
  auto print = design::stylus_print(inputs->setup, point);
  const auto tool = design::predict_tool(inputs->setup, point, surface);
  figures::StylusSheetInputs sheet{&tool, nullptr, std::nullopt, {}};
  if (space) {
    sheet.space = &*space;
    sheet.placement = design::place_predicted(*space->descriptor_map, tool);
    // A printer that cannot mix prints one material: each alone at the design's tip, placed.
    print.substitutes = design::single_material_substitutes(
        point, design::distance_to_target(inputs->setup, surface, *space->descriptor_map, *sheet.placement), {},
        model::space::GroupAim::largest);
    for (const auto& s : print.substitutes)
      std::cout << fmt::format("without mixing: {} is {:.3f} ± {:.3f} from the design in the space\n",
                               design::label(s.point), s.cost, s.cost_sd);
  }
  print.printer = printer;
  print_stylus_files(print, figures::export_stylus(o.output, print, sheet));
}

}  // namespace

void add_export_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto o = std::make_shared<ExportOptions>();
  auto* cmd = app.add_subcommand("export", "Write a design's stylus as files a printer takes (3MF, STL per region)");
  cmd->footer(
      "The stylus is the one `nibrig predict` simulates for the design (same template, materials,\n"
      "mesh size): each material region's surface as the FEM meshed it. The 3MF holds one part\n"
      "with an object per region and its material (a mixed tip: the fractions to mix); an STL per\n"
      "region is written beside it as <name>-<region>.stl, the recipe as <name>.json and the\n"
      "print sheet as <name>-sheet.png: the design, its recipe, its predicted mu and spectrum on\n"
      "--surface, and with --space its place in the space. With --printer the 3MF carries\n"
      "the printer's slicer settings (Metadata/Slic3r_PE.config) and <name>.ini is written for\n"
      "`prusa-slicer --load <name>.ini --export-gcode <name>.3mf`; a design the printer cannot\n"
      "make (a material it lacks, a mix it cannot mix, a tip below its nozzle or pixels) is refused.");
  cmd->add_option("DESIGN", o->design, "A design point (DM85:0.62,vero:0.38,tip=2.7mm) or a prediction file")
      ->required();
  cmd->add_option("-o,--output", o->output, "The 3MF file to write")->capture_default_str()->check(file_to_write());
  cmd->add_option("--template", o->inputs.design_template,
                  "Stylus the designs are built on (default: assets/designs/stylus_vero_tip2mm.json)");
  cmd->add_option("--materials", o->inputs.materials, "Material table (default: assets/materials.json)");
  cmd->add_option("--mesh-size", o->inputs.mesh_size, "Element size in metres (default: the template's)")
      ->check(stylus_metres("an element size"));
  cmd->add_option("--modes", o->inputs.modes, "Modes the sheet's prediction solves (default: the template's)")
      ->check(whole_in_range(1, 1000, "a number of modes"));
  cmd->add_option("--surface", o->surface,
                  "Surface the stylus is for: its predicted mu and spectrum go on the print sheet "
                  "(default: a prediction file's)");
  cmd->add_option("--space", o->space_file,
                  "Fitted space with a descriptor map: the design's place in it goes on the sheet");
  cmd->add_option("--forcing", o->forcing_model,
                  "Forcing model from `nibrig forcing fit` (default: the catalog's, cached)");
  cmd->add_option("--catalog", o->inputs.catalog, "Tool catalog JSON (default: the bundled one)");
  cmd->add_option("--printer", o->printer, printer_option_help());
  cmd->callback([o, global] {
    configure_logging(global->verbosity);
    run_export(*o);
  });
}

}  // namespace nibrig::ui::cli
