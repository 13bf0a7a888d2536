// `nibrig export DESIGN -o stylus.3mf`: a design point (or the design of a prediction file) as the
// files a printer takes — the stylus its prediction simulated, region by region as the FEM meshed
// it, in one 3MF and an STL per region (model/design/stylus_export.hpp).
#include <fmt/format.h>

#include <iostream>

#include "model/design/prediction_file.hpp"
#include "model/design/stylus_export.hpp"
#include "model/mechanics/region_surface.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/stylus_report.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {

namespace design = model::design;

void print_stylus_files(const design::StylusPrint& print, const design::StylusFiles& files) {
  std::cout << fmt::format("stylus {} ({}), meshed at {:.2f} mm:\n", design::label(print.point), print.design_name,
                           print.design.mesh_size * 1e3);
  for (const auto& region : print.regions)
    std::cout << fmt::format("  {}: {}, {} triangles, {:.1f} mm3\n", region.surface.name,
                             design::printer_material(region), region.surface.triangles.size(),
                             model::mechanics::enclosed_volume(region.surface) * 1e9);
  say_wrote(files.three_mf);
  for (const auto& stl : files.stls) say_wrote(stl);
  say_wrote(files.recipe);
}

namespace {

struct ExportOptions {
  std::string design;
  std::filesystem::path output = "stylus.3mf";
  model::forcing::ForcingInputOptions inputs;
};

design::DesignPoint design_to_export(const std::string& text) {
  std::error_code error;
  if (std::filesystem::is_regular_file(text, error)) return design::read_prediction_point(text);
  try {
    return design::parse_design_point(text);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("DESIGN", std::string(e.what()) +
                                             " (expected a design point such as \"DM85:0.62,vero:0.38,tip=2.7mm\" "
                                             "or a prediction file)");
  }
}

}  // namespace

void add_export_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto o = std::make_shared<ExportOptions>();
  auto* cmd = app.add_subcommand("export", "Write a design's stylus as files a printer takes (3MF, STL per region)");
  cmd->footer(
      "The stylus is the one `nibrig predict` simulates for the design (same template, materials,\n"
      "mesh size): each material region's surface as the FEM meshed it. The 3MF holds one part\n"
      "with an object per region and its material (a mixed tip: the fractions to mix); an STL per\n"
      "region is written beside it as <name>-<region>.stl, and the recipe as <name>.json.");
  cmd->add_option("DESIGN", o->design, "A design point (DM85:0.62,vero:0.38,tip=2.7mm) or a prediction file")
      ->required();
  cmd->add_option("-o,--output", o->output, "The 3MF file to write")->capture_default_str()->check(file_to_write());
  cmd->add_option("--template", o->inputs.design_template,
                  "Stylus the designs are built on (default: assets/designs/stylus_vero_tip2mm.json)");
  cmd->add_option("--materials", o->inputs.materials, "Material table (default: assets/materials.json)");
  cmd->add_option("--mesh-size", o->inputs.mesh_size, "Element size in metres (default: the template's)")
      ->check(stylus_metres("an element size"));
  cmd->callback([o, global] {
    configure_logging(global->verbosity);
    if (o->output.extension() != ".3mf")
      throw CLI::ValidationError("--output", "'" + o->output.string() + "' is not a .3mf file");
    const auto point = design_to_export(o->design);
    design::check_stylus_folder(o->output.parent_path());
    const auto print = design::stylus_print(o->inputs, point);
    print_stylus_files(print, design::write_stylus_files(o->output, print));
  });
}

}  // namespace nibrig::ui::cli
