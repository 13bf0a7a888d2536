// `nibrig catalog build <folder>`: every recording in a folder -> one catalog of descriptors.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "model/catalog/catalog_builder.hpp"
#include "model/catalog/friction_comparison.hpp"
#include "model/catalog/compact.hpp"
#include "model/catalog/merge.hpp"
#include "model/io/atomic_file.hpp"
#include "model/io/bundled_assets.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/measurement_figures.hpp"
#include "ui/options/number_checks.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"

namespace nibrig::ui::cli {

namespace {

struct CatalogOptions {
  std::filesystem::path folder;
  std::filesystem::path output = "catalog.json";
  std::filesystem::path report;
  std::filesystem::path threshold;
  double compact_step_hz = 0.0;
  int compact_digits = 4;
};

std::string friction_table(const model::catalog::CatalogBuild& build) {
  std::ostringstream csv;
  csv << "tool,surface,mu,mu_ci95_low,mu_ci95_high,upstream_mu,contact_begin_s,contact_end_s,"
         "mu_slope_per_m_s,source\n";
  for (const auto& f : build.friction) {
    csv << f.tool << ',' << f.surface << ',' << f.fit.mu << ',' << f.fit.mu_ci_low << ','
        << f.fit.mu_ci_high << ',' << f.upstream_mu << ','
        << static_cast<double>(f.fit.contact.begin) / f.sample_rate_hz << ','
        << static_cast<double>(f.fit.contact.end) / f.sample_rate_hz << ','
        << f.fit.speed_slope_per_m_s << ',' << f.source.filename().string() << '\n';
  }
  return csv.str();
}

std::string vibration_table(const model::catalog::CatalogBuild& build) {
  std::ostringstream csv;
  csv << "tool,surface,weighted_mean,weighted_power,contact_begin_s,steps,warnings,source\n";
  for (const auto& v : build.vibration) {
    csv << v.tool << ',' << v.surface << ',' << v.descriptors.weighted_mean << ','
        << v.descriptors.weighted_power << ','
        << static_cast<double>(v.contact_begin) / v.sample_rate_hz << ',' << v.steps.size() << ','
        << v.warnings.size() << ',' << v.source.filename().string() << '\n';
  }
  return csv.str();
}

// A few lines a person reads first: what was processed and how μ compares with the paper.
void print_summary(const model::catalog::CatalogBuild& build, std::ostream& out) {
  out << "processed " << build.friction.size() << " friction and " << build.vibration.size()
      << " vibration recordings; " << build.catalog.pairings.size() << " tool-surface pairs";
  if (!build.skipped.empty()) out << "; skipped " << build.skipped.size() << " other files";
  out << "\n";
  if (build.friction.empty()) return;
  const auto c = model::catalog::compare_with_upstream(build.friction);
  out << "mu (contact-detected fit): " << c.fit_min << " .. " << c.fit_max << ", median "
      << c.fit_median << "\n";
  out << "mu (upstream recipe, rows 5000-20000): " << c.upstream_min << " .. " << c.upstream_max
      << ", median " << c.upstream_median << "\n";
  out << "mean |fit - upstream|: " << c.mean_abs_difference
      << "; paper's stated range: 0.13 .. 0.33\n";
}

void build(const CatalogOptions& options, unsigned threads) {
  namespace catalog = model::catalog;
  const auto threshold = model::measure::ThresholdCurve::load(
      options.threshold.empty() ? model::io::default_threshold_curve() : options.threshold);
  const auto found = catalog::find_recordings(options.folder);
  for (const auto& s : found.skipped) spdlog::info("skipped {}", s);
  if (found.files.empty()) {
    throw std::runtime_error(options.folder.string() + ": no recordings found");
  }
  model::io::output_target(options.output);  // not one of the recordings, before minutes of work
  Progress progress("analysing", found.files.size());
  const catalog::AnalysisOptions analysis_options;
  auto result =
      catalog::build_catalog(found, threshold, analysis_options, threads,
                             [&](const auto& path) { progress.advance(path.filename()); });
  if (options.compact_step_hz > 0.0) {
    result.catalog =
        catalog::compact_catalog(result.catalog, options.compact_step_hz, options.compact_digits);
  }
  ensure_folder(options.output.parent_path());
  model::io::write_catalog(options.output, result.catalog,
                           options.compact_step_hz > 0.0 ? model::io::JsonLayout::compact
                                                         : model::io::JsonLayout::indented);
  print_summary(result, std::cout);
  std::cout << "wrote " << options.output.string() << "\n";
  if (!options.report.empty()) {
    ensure_folder(options.report);
    write_text_file(options.report / "friction.csv", friction_table(result));
    write_text_file(options.report / "vibration.csv", vibration_table(result));
    if (!result.friction.empty())
      plot_catalog_friction(result.catalog, options.report / "friction.png");
    for (const auto& v : result.vibration) {
      plot_velocity_spectrum(
          v.spectrum, "Velocity-binned spectrum: " + v.tool + " on " + v.surface,
          options.report / (v.tool + "_" + v.surface + "_velocity_spectrum.png"));
    }
    std::cout << "wrote report to " << options.report.string() << "\n";
  }
}

struct MergeOptions {
  std::vector<std::filesystem::path> catalogs;
  std::filesystem::path output;
};

void merge(const MergeOptions& options) {
  std::vector<model::catalog::NamedCatalog> catalogs;
  for (const auto& file : options.catalogs)
    catalogs.push_back({file.string(), model::io::read_catalog(file)});
  const auto merged = model::catalog::merge_catalogs(catalogs);
  ensure_folder(options.output.parent_path());
  model::io::write_catalog(options.output, merged);
  std::cout << merged.tools.size() << " tools, " << merged.surfaces.size() << " surfaces, "
            << merged.pairings.size() << " pairings from " << catalogs.size() << " catalogs\n";
  say_wrote(options.output);
}

}  // namespace

void add_catalog_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* catalog =
      app.add_subcommand("catalog", "Tool catalogs: physical descriptors of tools on surfaces");
  catalog->require_subcommand(1);
  auto options = std::make_shared<CatalogOptions>();
  auto* cmd =
      catalog->add_subcommand("build", "Every recording below a folder -> one tool catalog");
  cmd->footer(
      "Analyse every recording in a folder tree (the paper's friction and accelerometer files,\n"
      "rig session folders) and write one catalog JSON with the descriptors of each tool-surface\n"
      "pair and the provenance of every number. Prints a summary comparing mu with the paper.");
  cmd->add_option("folder", options->folder, "Folder to search recursively")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", options->output, "Catalog JSON to write")
      ->capture_default_str()
      ->check(file_to_write());
  cmd->add_option("--report", options->report,
                  "Also write friction.csv, vibration.csv and PNG figures to this folder");
  cmd->add_option("--threshold", options->threshold, "Detection-threshold curve CSV")
      ->check(CLI::ExistingFile);
  cmd->add_option("--compact", options->compact_step_hz,
                  "Resample spectra to this frequency step (Hz), round them and write one-line "
                  "JSON, for bundling")
      ->check(in_range(0.01, 1000, "a frequency step in Hz"));
  cmd->add_option("--digits", options->compact_digits, "Significant digits kept with --compact")
      ->check(whole_in_range(2, 17, "a number of significant digits"))
      ->capture_default_str();
  cmd->callback([options, global] {
    configure_logging(global->verbosity);
    build(*options, worker_threads(*global));
  });

  auto merging = std::make_shared<MergeOptions>();
  auto* merge_cmd = catalog->add_subcommand("merge", "Several catalogs -> one (the bundled and a lab's own)");
  merge_cmd->footer(
      "A lab's catalog of its own prints beside the bundled one: predictions of its material read\n"
      "their friction from it while a design's targets stay the paper's tools. A tool measured on\n"
      "one surface in two catalogs is refused: keep one measurement.");
  merge_cmd->add_option("catalogs", merging->catalogs, "Catalog JSON files, two or more")
      ->required()
      ->expected(2, -1)
      ->check(CLI::ExistingFile);
  merge_cmd->add_option("-o,--output", merging->output, "Catalog JSON to write")->required()->check(file_to_write());
  merge_cmd->callback([merging, global] {
    configure_logging(global->verbosity);
    merge(*merging);
  });
}

}  // namespace nibrig::ui::cli
