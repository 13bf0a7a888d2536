// `nibrig design`: the printable design that feels closest to a target tool on an artificial
// surface (Sec. 6.2, Fig. 17) — along the line between two designs, or over the whole mix × tip
// range — with the optimum, its distance, the runners-up and the path drawn in the space.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <iostream>
#include <optional>

#include "model/design/design_search.hpp"
#include "model/design/design_search_file.hpp"
#include "model/design/stylus_export.hpp"
#include "model/io/catalog_file.hpp"
#include "model/space/space_file.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/space/space_inputs.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/design_reports.hpp"
#include "ui/cli/elapsed.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/logging.hpp"
#include "ui/options/number_checks.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/stylus_report.hpp"
#include "ui/figures/stylus_sheet.hpp"

namespace nibrig::ui::cli {

namespace {

namespace design = model::design;
namespace space = model::space;

struct DesignOptions {
  std::string target;   // "tool/surface", judged in the space or placed from the catalog
  std::string surface;  // the artificial surface the stylus is for
  std::filesystem::path space_file;
  std::vector<std::string> between;  // two designs: a line search; none: the whole range
  std::string mix = "vero,DM85";     // the two materials of the range search
  std::filesystem::path forcing_model;
  ForcingInputOptions inputs;
  int runners_up = 4;
  std::filesystem::path output = "design_search.json";
  std::filesystem::path plot;
  std::filesystem::path export_folder;  // the optimum's stylus files
};

void run_design(const DesignOptions& o) {
  if (!o.export_folder.empty()) design::check_stylus_folder(o.export_folder);  // before minutes of search
  const auto catalog_path =
      o.inputs.catalog.empty() ? model::io::default_catalog() : o.inputs.catalog;
  const space::SpaceFile space_file = space::read_space_file(o.space_file);
  if (!space_file.descriptor_map)
    throw std::invalid_argument(o.space_file.string() +
                                " has no descriptor map (fit it with --descriptors): designs are "
                                "placed from their predicted descriptors");
  model::space::StimulusLocator locator(space_file, o.space_file, catalog_path);
  // An unknown --target is a usage error that names the option and the choices, as other options'
  // refusals do; the locator's own reason (which file lacks it) is kept in the message.
  const space::Placement target = [&] {
    try {
      return locator.locate(o.target, o.space_file);
    } catch (const std::exception& e) {  // FormatError from the catalog, invalid_argument here
      std::string judged;
      for (const auto& s : space_file.stimuli) judged += (judged.empty() ? "" : ", ") + s;
      throw CLI::ValidationError(
          "--target", "'" + o.target + "' cannot be placed: " + e.what() +
                          "; choices: a stimulus judged in the space (" + judged +
                          ") or a tool/surface pairing of " + catalog_path.string());
    }
  }();

  std::optional<design::DesignPoint> a, b;
  if (!o.between.empty()) {
    if (o.between.size() != 2)
      throw CLI::ValidationError("--between", "takes two designs, e.g. vero,tip=1mm DM85,tip=4mm");
    a = design::parse_design_point(o.between[0]);
    b = design::parse_design_point(o.between[1]);
  }
  design::RangeSearchOptions range;
  if (const auto comma = o.mix.find(','); comma != std::string::npos) {
    range.first_material = o.mix.substr(0, comma);
    range.second_material = o.mix.substr(comma + 1);
  } else {
    throw CLI::ValidationError("--mix", "takes two materials, e.g. vero,DM85");
  }

  if (o.forcing_model.empty() && warnings_shown())  // seconds of silence otherwise, as in predict
    std::cerr << "no --forcing given: the catalog's default forcing model (fitted once, then kept in the user cache)\n";
  const auto inputs = load_prediction_inputs(o.inputs, o.forcing_model, std::nullopt, design_progress());
  const auto& model = inputs->model;
  range.min_tip_m = model.tip_log_gain.begin()->first;
  range.max_tip_m = model.tip_log_gain.rbegin()->first;

  std::size_t evaluations = 0;
  const design::Evaluate distance =
      design::distance_to_target(inputs->setup, o.surface, *space_file.descriptor_map, target);
  const design::Evaluate counted = [&](const design::DesignPoint& p) {
    auto c = distance(p);
    spdlog::debug("{}: distance {:.3f}", design::to_string(p), c.distance);
    ++evaluations;
    return c;
  };
  const auto start = std::chrono::steady_clock::now();
  const design::LineSearchOptions line;
  const auto last_of_scan = static_cast<std::size_t>(line.scan_points - 1);
  std::optional<Progress> bar;  // made with the first candidate, when the search's total is known
  const design::SearchProgress progress = [&](const design::Candidate& c, std::size_t,
                                              std::size_t total) {
    if (!bar) bar.emplace("predicting designs", total);
    bar->advance(design::to_string(c.point));
  };
  const design::SearchResult result = a ? design::line_search(*a, *b, counted, line, progress)
                                        : design::range_search(counted, range, progress);
  bar.reset();  // ends the bar's line before the results, also when it stopped short of its total
  const double seconds = seconds_since(start);

  const std::string how =
      a ? fmt::format("along the line {} -> {}", o.between[0], o.between[1])
        : fmt::format("over {} to {} x tips {:g}-{:g} mm", range.first_material,
                      range.second_material, range.min_tip_m * 1e3, range.max_tip_m * 1e3);
  std::cout << fmt::format("target {} ({}); designs on {} {}: {} predicted in {:.1f} s\n",
                           o.target, locator.placed(o.target) ? "placed from its descriptors" : "judged",
                           o.surface, how, evaluations, seconds);
  const auto& best = result.best();
  std::cout << fmt::format("optimum {}: distance {:.3f} ± {:.3f}, mu {:.3f}, weighted mean vibration {:.4g}\n",
                           design::label(best.point), best.distance, best.distance_sd, best.mu,
                           best.weighted_mean);
  const auto runners = result.runners_up(static_cast<std::size_t>(o.runners_up));
  for (std::size_t k = 0; k < runners.size(); ++k) {
    const auto& c = result.evaluated[runners[k]];
    std::cout << fmt::format("  runner-up {}: {} distance {:.3f} ± {:.3f}\n", k + 1,
                             design::label(c.point), c.distance, c.distance_sd);
  }
  if (a) {
    const auto& first = result.evaluated.front();
    std::cout << fmt::format("  the two designs themselves: {} {:.3f}, {} {:.3f}\n",
                             o.between[0], first.distance, o.between[1],
                             result.evaluated[last_of_scan].distance);
  }

  ensure_folder(o.output.parent_path());
  design::write_design_search(o.output, result,
                              {o.target, o.surface, how, seconds,
                               static_cast<std::size_t>(o.runners_up), o.space_file.string()});
  say_wrote(o.output);
  if (!o.plot.empty()) {
    ensure_folder(o.plot.parent_path());
    std::vector<std::size_t> ends;
    if (a) ends = {0, last_of_scan};
    write_search_plot(space_file, o.target, locator.placed(o.target) ? &target : nullptr, result,
                      ends, o.surface, o.plot);
    say_wrote(o.plot);
  }
  if (!o.export_folder.empty()) {
    auto print = design::stylus_print(inputs->setup, best.point);
    // A printer that cannot mix prints one material: each alone at the optimum's tip, placed.
    print.substitutes = design::single_material_substitutes(
        best.point, design::distance_to_target(inputs->setup, o.surface, *space_file.descriptor_map, best.placement),
        target);
    for (const auto& s : print.substitutes)
      std::cout << fmt::format("without mixing: {} is {:.3f} ± {:.3f} from the optimum ({:.3f} ± {:.3f} from the target)\n",
                               design::label(s.point), s.cost, s.cost_sd, s.to_target, s.to_target_sd);
    const auto tool = design::predict_tool(inputs->setup, best.point, o.surface);  // the sheet's spectrum
    figures::StylusSheetInputs sheet{&tool, &space_file, best.placement, {}};
    sheet.targets.push_back({o.target, locator.placed(o.target) ? std::optional(target) : std::nullopt,
                             best.distance, best.distance_sd});
    print_stylus_files(print, figures::export_stylus(o.export_folder / "stylus.3mf", print, sheet));
  }
}

}  // namespace

void add_design_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto o = std::make_shared<DesignOptions>();
  auto* cmd = app.add_subcommand(
      "design", "Find the printable design that feels closest to a target tool (Sec. 6.2)");
  cmd->footer(
      "Every candidate is predicted (as `nibrig predict`) and placed in the space from its\n"
      "descriptors; the distance to the target is between the placements' means, with its\n"
      "spread from their uncertainties. --between searches the line between two designs (a scan of\n"
      "9 points, then golden sections); otherwise the whole range of a two-material mix (--mix)\n"
      "and the fitted tips (a 5 x 4 grid refined twice).");
  cmd->add_option("--target", o->target, "Target tool as tool/surface (e.g. cryon/office)")
      ->required();
  cmd->add_option("--surface", o->surface, "Surface the stylus is for (glass, protector, ...)")
      ->required();
  cmd->add_option("--space", o->space_file, "Fitted space with a descriptor map (space fit)")
      ->required();
  cmd->add_option("--between", o->between, "Two designs: search the line between them")
      ->expected(2);
  cmd->add_option("--mix", o->mix, "The two materials of the range search")->capture_default_str();
  cmd->add_option("--forcing", o->forcing_model,
                  "Forcing model from `nibrig forcing fit` (default: the catalog's, cached)");
  cmd->add_option("--catalog", o->inputs.catalog, "Tool catalog JSON (default: the bundled one)");
  cmd->add_option("--template", o->inputs.design_template,
                  "Stylus the designs are built on (default: assets/designs/stylus_vero_tip2mm.json)");
  cmd->add_option("--materials", o->inputs.materials, "Material table (default: assets/materials.json)");
  cmd->add_option("--modes", o->inputs.modes, "Modes of each design (default: the template's)")
      ->check(whole_in_range(1, 1000, "a number of modes"));
  cmd->add_option("--mesh-size", o->inputs.mesh_size, "Element size in metres")
      ->check(stylus_metres("an element size"));
  cmd->add_option("--runners-up", o->runners_up, "How many runners-up to report")
      ->capture_default_str()
      ->check(whole_in_range(0, 1000, "a number of runners-up"));
  cmd->add_option("-o,--output", o->output, "Search JSON to write")
      ->capture_default_str()
      ->check(file_to_write());
  cmd->add_option("--plot", o->plot, "PNG of the path in the space (Fig. 17)")
      ->check(file_to_write());
  cmd->add_option("--export", o->export_folder,
                  "Folder to write the optimum's stylus into: stylus.3mf, an STL per region, the recipe and the print sheet");
  cmd->callback([o, global] {
    configure_logging(global->verbosity);
    run_design(*o);
  });
}

}  // namespace nibrig::ui::cli
