// `nibrig design`: the printable design that feels closest to a target tool on an artificial
// surface (Sec. 6.2, Fig. 17) — along the line between two designs, or over the whole mix × tip
// range — with the optimum, its distance, the runners-up and the path drawn in the space.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <iostream>
#include <map>
#include <optional>

#include "model/design/design_constraints.hpp"
#include "model/design/design_grid_file.hpp"
#include "model/design/design_search.hpp"
#include "model/design/design_search_file.hpp"
#include "model/design/design_search_request.hpp"
#include "model/design/printability.hpp"
#include "model/design/stylus_export.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/numeric/cancellation.hpp"
#include "model/space/space_file.hpp"
#include "model/space/space_inputs.hpp"
#include "ui/cli/app.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/design_reports.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/interrupt_scope.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/stylus_report.hpp"
#include "ui/figures/stylus_sheet.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {

namespace {

namespace design = model::design;
namespace space = model::space;

struct DesignOptions {
  std::vector<std::string> targets;  // "tool/surface", judged in the space or placed from the catalog
  std::string aim = "largest";       // of a group's distances: largest or mean
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
  std::string printer;                  // --printer, for --export
  std::optional<double> min_tip_mm, max_tip_mm;
  std::vector<std::string> allow;  // materials a printer may load
  std::string cost;                // "vero=1,DM85=3"
  std::optional<double> max_cost;
  bool grid = false;  // through the design grid, the FEM only where its error could matter
};

// --cost "vero=1,DM85=3": a number per material.
std::map<std::string, double> parse_costs(const std::string& text) {
  std::map<std::string, double> out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    const auto eq = item.find('=');
    double value = 0;
    std::size_t used = 0;
    try {
      if (eq != std::string::npos) value = std::stod(item.substr(eq + 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (eq == std::string::npos || eq == 0 || used == 0 || used != item.size() - eq - 1 || !std::isfinite(value))
      throw CLI::ValidationError("--cost", "'" + item + "' is not material=number (e.g. vero=1,DM85=3)");
    out[item.substr(0, eq)] = value;
    at = comma + 1;
  }
  return out;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The request's fields as this command's options.
std::string design_option(design::DesignSearchField field) {
  using Field = design::DesignSearchField;
  switch (field) {
    case Field::targets:
      return "--target";
    case Field::surface:
      return "--surface";
    case Field::space:
      return "--space";
    case Field::aim:
      return "--aim";
    case Field::between:
      return "--between";
    case Field::mix:
      return "--mix";
    case Field::min_tip:
      return "--min-tip-mm";
    case Field::max_tip:
      return "--max-tip-mm";
    case Field::allow:
      return "--allow";
    case Field::cost:
      return "--cost";
    case Field::max_cost:
      return "--max-cost";
    case Field::printer:
      return "--printer";
  }
  return design::field_name(field);
}

// The options as the library's request; the space file is read and the targets placed when the
// request asks for them, after the options' own checks.
struct DesignRequestOptions {
  const DesignOptions& o;
  std::filesystem::path catalog_path;
  std::optional<space::SpaceFile> space_file;
  std::optional<space::StimulusLocator> locator;

  design::DesignSearchTargets targets() {
    space_file = space::read_space_file(o.space_file);
    if (!o.export_folder.empty()) design::check_stylus_outputs(o.export_folder / "stylus.3mf");
    design::DesignSearchTargets out{space_file->descriptor_map, {}, o.targets};
    if (!out.descriptor_map)
      return out;  // refused as --space: placing a catalog tool needs the map
    locator.emplace(*space_file, o.space_file, catalog_path);
    for (const auto& name : o.targets) out.placements.push_back(locate(name));
    return out;
  }

  // An unknown --target is a usage error that names the option and the choices, as other
  // options' refusals do; the locator's own reason (which file lacks it) is kept in the message.
  space::Placement locate(const std::string& name) {
    try {
      return locator->locate(name, o.space_file);
    } catch (const std::exception& e) {  // FormatError from the catalog, invalid_argument here
      throw CLI::ValidationError("--target", "'" + name + "' cannot be placed: " + e.what() +
                                                 "; choices: a stimulus judged in the space (" +
                                                 joined(space_file->stimuli) +
                                                 ") or a tool/surface pairing of " +
                                                 catalog_path.string());
    }
  }
};

design::DesignSearchRequest design_request(
    const DesignOptions& o, DesignRequestOptions& placing,
    const std::optional<model::io::PrinterProfile>& printer) {
  design::DesignSearchRequest r;
  r.targets = [&placing] { return placing.targets(); };
  r.surface = o.surface;
  r.aim = design::parse_group_aim(o.aim, design_option);
  if (o.min_tip_mm) r.constraints.min_tip_m = *o.min_tip_mm * 1e-3;
  if (o.max_tip_mm) r.constraints.max_tip_m = *o.max_tip_mm * 1e-3;
  r.constraints.materials = o.allow;
  r.constraints.cost = parse_costs(o.cost);
  r.constraints.max_cost = o.max_cost;
  if (!o.between.empty()) {
    if (o.between.size() != 2)
      throw CLI::ValidationError("--between", "takes two designs, e.g. vero,tip=1mm DM85,tip=4mm");
    r.between.emplace(design::parse_design_point(o.between[0]),
                      design::parse_design_point(o.between[1]));
  }
  const auto comma = o.mix.find(',');
  if (comma == std::string::npos)
    throw CLI::ValidationError("--mix", "takes two materials, e.g. vero,DM85");
  r.first_material = o.mix.substr(0, comma);
  r.second_material = o.mix.substr(comma + 1);
  r.printer = printer;
  return r;
}

void run_design(const DesignOptions& o) {
  if (!o.export_folder.empty()) design::check_stylus_folder(o.export_folder);  // before minutes of search
  if (!o.printer.empty() && o.export_folder.empty())
    throw CLI::ValidationError("--printer", "is the printer of --export: give --export too");
  const auto printer = printer_option(o.printer);
  DesignRequestOptions placing{
      o, o.inputs.catalog.empty() ? model::io::default_catalog() : o.inputs.catalog, {}, {}};
  // Everything refusable is refused here, named as the options, before the forcing model is loaded.
  const design::DesignSearch search = [&] {
    try {
      return design::DesignSearch(design_request(o, placing, printer), design_option);
    } catch (const design::DesignSearchRefused& e) {
      throw CLI::ValidationError(e.what());
    }
  }();
  const auto& space_file = *placing.space_file;
  auto& locator = *placing.locator;
  const auto& targets = search.targets().placements;
  const auto& constraints = search.request().constraints;
  const auto aim = search.request().aim;
  const bool group = search.group();
  const std::string target_words =
      group ? fmt::format("{} ({} of {} targets)", joined(o.targets), o.aim == "mean" ? "mean distance" : "largest distance",
                          o.targets.size())
            : o.targets.front();

  if (o.forcing_model.empty() && warnings_shown())  // seconds of silence otherwise, as in predict
    std::cerr << "no --forcing given: the catalog's default forcing model (fitted once, then kept in the user cache)\n";
  const auto inputs =
      load_prediction_inputs(o.inputs, o.forcing_model, std::nullopt, design_progress());

  std::optional<Progress> bar;  // made with the first candidate, when the search's total is known
  const design::SearchProgress progress = [&](const design::Candidate& c, std::size_t,
                                              std::size_t total) {
    if (!bar) {
      spdlog::info("design search: {} designs to predict", total);
      bar.emplace("predicting designs", total);
    }
    bar->advance(design::to_string(c.point));
  };
  InterruptScope interrupt;
  std::optional<design::DesignResponseGrid> grid;
  if (o.grid) {
    const auto axes = design::default_grid_axes(*inputs, search.request().first_material,
                                                search.request().second_material);
    try {
      grid = design::cached_design_response_grid(
          *inputs, axes, progress_bar("solving the design grid (once, then kept)"),
          interrupt.token());
    } catch (const model::numeric::Cancelled&) {
      throw Interrupted("the design grid was stopped; nothing was written");
    }
  }
  const auto searched = [&] {
    try {
      return grid ? search.run(*inputs, *grid, interrupt.token(), progress)
                  : search.run(*inputs, interrupt.token(), progress);
    } catch (const design::DesignSearchRefused& e) {  // a surface the forcing model lacks
      throw CLI::ValidationError(e.what());
    } catch (const model::numeric::Cancelled&) {
      bar.reset();
      throw Interrupted("the design search was stopped; nothing was written");
    }
  }();
  bar.reset();  // ends the bar's line before the results, also when it stopped short of its total
  const auto& result = searched.result;

  std::string placed_words;
  for (const auto& name : o.targets)
    placed_words += fmt::format("{}{} ({})", placed_words.empty() ? "" : ", ", name,
                                locator.placed(name) ? "placed from its descriptors" : "judged");
  std::cout << fmt::format("{} {}; designs on {} {}: {} predicted in {:.1f} s\n",
                           group ? "targets" : "target", placed_words, o.surface, searched.how,
                           searched.evaluations, searched.seconds);
  if (grid)
    std::cout << fmt::format(
        "the grid's error measured {:.2g} space units: the FEM solved {} (the designs it could "
        "change and the cells they lie in)\n",
        searched.grid_error, searched.fem_solves);
  if (constraints.any()) std::cout << "within " << design::describe(constraints) << "\n";
  const auto& best = result.best();
  std::cout << fmt::format("optimum {}: {}distance {:.3f} ± {:.3f}, mu {:.3f}, weighted mean vibration {:.4g}{}\n",
                           design::label(best.point), group ? o.aim + " " : "", best.distance, best.distance_sd,
                           best.mu, best.weighted_mean,
                           constraints.cost.empty() ? std::string()
                                                    : fmt::format(", cost {:.4g}", design::design_cost(best.point, constraints.cost)));
  if (group)
    for (std::size_t t = 0; t < o.targets.size(); ++t)
      std::cout << fmt::format("  to {}: {:.3f} ± {:.3f}\n", o.targets[t], best.target_distances[t],
                               best.target_distance_sds[t]);
  const auto runners = result.runners_up(static_cast<std::size_t>(o.runners_up));
  for (std::size_t k = 0; k < runners.size(); ++k) {
    const auto& c = result.evaluated[runners[k]];
    std::cout << fmt::format("  runner-up {}: {} distance {:.3f} ± {:.3f}\n", k + 1,
                             design::label(c.point), c.distance, c.distance_sd);
  }
  // The scan's ends: the two designs, or the ends of the segment the constraints allow of the line.
  if (!searched.line_ends.empty()) {
    const auto& first = result.evaluated[searched.line_ends.front()];
    const auto& last = result.evaluated[searched.line_ends.back()];
    std::cout << fmt::format("  {}: {} {:.3f}, {} {:.3f}\n",
                             constraints.any() ? "the ends of the line allowed" : "the two designs themselves",
                             design::label(first.point), first.distance, design::label(last.point), last.distance);
  }

  ensure_folder(o.output.parent_path());
  design::DesignSearchDescription description{target_words,
                                              o.surface,
                                              searched.how,
                                              searched.seconds,
                                              static_cast<std::size_t>(o.runners_up),
                                              o.space_file.string(),
                                              {},
                                              {},
                                              constraints,
                                              {},
                                              {}};
  if (group) description.targets = o.targets, description.aim = o.aim;
  if (grid)
    description.guided =
        design::GuidedDescription{searched.fem_solved, searched.grid_error, searched.fem_solves};
  for (const auto& name : o.targets)
    if (locator.placed(name)) description.placed.push_back(name);
  design::write_design_search(o.output, result, description);
  say_wrote(o.output);
  if (!o.plot.empty()) {
    ensure_folder(o.plot.parent_path());
    std::vector<figures::PlacedTool> placed_targets;
    for (std::size_t t = 0; t < targets.size(); ++t)
      if (locator.placed(o.targets[t])) placed_targets.push_back({o.targets[t], targets[t], "target", true});
    write_search_plot(space_file, target_words, placed_targets, result, searched.line_ends,
                      o.surface, o.plot);
    say_wrote(o.plot);
  }
  if (!o.export_folder.empty()) {
    auto print = design::stylus_print(inputs->setup, best.point);
    // A printer that cannot mix prints one material: each alone at the optimum's tip, placed.
    print.substitutes = design::single_material_substitutes(
        best.point,
        design::distance_to_target(inputs->setup, o.surface, search.descriptor_map(),
                                   best.placement),
        targets, aim);
    for (auto& s : print.substitutes) {
      s.outside_constraints = design::broken_constraint(s.point, constraints);
      std::cout << fmt::format("without mixing: {} is {:.3f} ± {:.3f} from the optimum ({:.3f} ± {:.3f} from {}){}\n",
                               design::label(s.point), s.cost, s.cost_sd, s.to_target.value_or(0.0), s.to_target_sd,
                               group ? "the targets, " + o.aim : "the target",
                               s.outside_constraints.empty() ? "" : "; outside the constraints: " + s.outside_constraints);
    }
    print.printer = printer;
    if (printer) design::check_printable(*printer, print);  // before the sheet's prediction
    const auto tool = design::predict_tool(inputs->setup, best.point, o.surface);  // the sheet's spectrum
    figures::StylusSheetInputs sheet{&tool, &space_file, best.placement, {}, o.aim};
    for (std::size_t t = 0; t < targets.size(); ++t)
      sheet.targets.push_back({o.targets[t], locator.placed(o.targets[t]) ? std::optional(targets[t]) : std::nullopt,
                               best.target_distances[t], best.target_distance_sds[t]});
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
      "and the fitted tips (a 5 x 4 grid refined twice). Several --target: one design for the\n"
      "group, minimising the largest (or --aim mean) distance. --min-tip-mm, --max-tip-mm,\n"
      "--allow and --max-cost (with --cost) restrict both searches to the designs they allow.");
  // Required unless `design loop` is run (its own options), so checked in the callback.
  cmd->add_option(
         "--target", o->targets,
         "Target tool as tool/surface (e.g. cryon/office); several: one design for the group")
      ->take_all();
  cmd->add_option("--aim", o->aim, "A group's distance to minimise: largest or mean")->capture_default_str();
  cmd->add_option("--min-tip-mm", o->min_tip_mm, "Smallest tip diameter allowed (mm)")
      ->check(in_range(design::kSmallestConstraintTipMm, design::kLargestConstraintTipMm, "a tip diameter in mm"));
  cmd->add_option("--max-tip-mm", o->max_tip_mm, "Largest tip diameter allowed (mm)")
      ->check(in_range(design::kSmallestConstraintTipMm, design::kLargestConstraintTipMm, "a tip diameter in mm"));
  cmd->add_option("--allow", o->allow, "Materials a printer may load (default: all), e.g. vero,DM85")
      ->delimiter(',');
  cmd->add_option("--cost", o->cost, "A cost or durability proxy per material, e.g. vero=1,DM85=3");
  cmd->add_option("--max-cost", o->max_cost, "Largest cost of a design's mix (fractions times --cost)")
      ->check(in_range(0, design::kLargestDesignCost, "a cost of a design's mix"));
  cmd->add_option("--surface", o->surface, "Surface the stylus is for (glass, protector, ...)");
  cmd->add_option("--space", o->space_file, "Fitted space with a descriptor map (space fit)");
  cmd->add_flag(
      "--grid", o->grid,
      "Search through the design grid (solved once, then kept), the FEM solved only for the "
      "designs the grid's measured error could make the optimum: seconds instead of minutes");
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
  cmd->add_option("--printer", o->printer, printer_option_help());
  add_design_loop_command(cmd, global);
  cmd->callback([o, global, cmd] {
    if (cmd->got_subcommand("loop")) return;
    for (const char* name : {"--target", "--surface", "--space"})
      if (cmd->count(name) == 0) throw CLI::RequiredError(name);
    configure_logging(global->verbosity);
    run_design(*o);
  });
}

}  // namespace nibrig::ui::cli
