// `nibrig demo`: the main job on the bundled default. Runs the measurement pipeline's descriptor
// stage on the derived spectra and friction coefficients bundled in assets/ (the raw recordings are
// not redistributed) and writes a report folder a person can read.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <future>
#include <iostream>
#include <map>
#include <sstream>

#include "model/io/catalog_file.hpp"
#include "model/io/folder_result.hpp"
#include "model/measure/descriptors.hpp"
#include "model/measure/threshold_curve.hpp"
#include "model/io/bundled_assets.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/demo_forcing.hpp"
#include "ui/cli/demo_mechanics.hpp"
#include "ui/cli/demo_render.hpp"
#include "ui/cli/demo_rig.hpp"
#include "ui/cli/demo_space.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/measurement_figures.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"

namespace nibrig::ui::cli {

namespace {

// The demo's parts, in the order they run; `--only` picks some (a test about one part runs it alone).
const std::vector<std::string> kSections{"descriptors", "mechanics", "space", "forcing", "render", "rig"};

struct DemoOptions {
  std::filesystem::path output = "nibrig-demo";
  std::filesystem::path catalog;
  std::vector<std::string> only;  // empty: every part
};

std::string descriptors_csv(const model::io::Catalog& catalog, int max_bands) {
  std::ostringstream csv;
  csv << "tool,surface,mu,mu_ci95_low,mu_ci95_high,weighted_mean,weighted_power";
  for (int b = 0; b < max_bands; ++b) csv << ",band" << max_bands << "_" << b + 1;
  csv << "\n";
  for (const auto& p : catalog.pairings) {
    csv << p.tool << ',' << p.surface << ',';
    if (p.friction) {
      csv << p.friction->mu << ',' << p.friction->mu_ci_low << ',' << p.friction->mu_ci_high;
    } else {
      csv << ",,";
    }
    csv << ',';
    if (p.vibration) {
      csv << p.vibration->weighted_mean << ',' << p.vibration->weighted_power;
      const auto bands = p.vibration->band_energies.find(max_bands);
      for (int b = 0; b < max_bands; ++b) {
        csv << ',';
        if (bands != p.vibration->band_energies.end())
          csv << bands->second[static_cast<std::size_t>(b)];
      }
    } else {
      csv << ',' << std::string(static_cast<std::size_t>(max_bands), ',');
    }
    csv << '\n';
  }
  return csv.str();
}

// The descriptor stage of the pipeline, run on the bundled spectra: weighting by the detection
// threshold, mean weighted value, weighted power and band energies (Sec. 4.4). Every later part
// reads the catalog weighted; only this one writes its report.
DemoSection run_descriptor_demo(const model::io::Catalog& catalog,
                                const std::filesystem::path& catalog_path,
                                const model::measure::ThresholdCurve& threshold,
                                std::size_t vibration_pairs, const std::filesystem::path& output,
                                int max_bands) {
  std::size_t friction_pairs = 0;
  for (const auto& p : catalog.pairings)
    if (p.friction) ++friction_pairs;

  ensure_folder(output / "spectra");
  model::io::write_catalog(output / "catalog.json", catalog);
  write_text_file(output / "descriptors.csv", descriptors_csv(catalog, max_bands));
  if (friction_pairs > 0) plot_catalog_friction(catalog, output / "friction.png");
  Progress progress("figures", vibration_pairs);
  for (const auto& p : catalog.pairings) {
    if (!p.vibration) continue;
    plot_velocity_spectrum(p.vibration->spectrum,
                           "Velocity-binned spectrum: " + p.tool + " on " + p.surface,
                           output / "spectra" / (p.tool + "_" + p.surface + ".png"));
    progress.advance(p.tool + "_" + p.surface);
  }

  DemoSection section;
  section.numbers = {{"tools", catalog.tools.size()},
                     {"surfaces", catalog.surfaces.size()},
                     {"pairs", catalog.pairings.size()},
                     {"friction_pairs", friction_pairs},
                     {"vibration_pairs", vibration_pairs}};
  std::ostringstream summary;
  summary << "nibrig demo: measurement pipeline on the bundled default ("
          << catalog_path.filename().string() << ")\n"
          << "  " << catalog.tools.size() << " tools, " << catalog.surfaces.size() << " surfaces, "
          << catalog.pairings.size() << " pairs: " << friction_pairs << " with friction, "
          << vibration_pairs << " with vibration spectra\n";
  if (friction_pairs > 0) {
    double lo = 1e9, hi = -1e9;
    for (const auto& p : catalog.pairings) {
      if (!p.friction) continue;
      lo = std::min(lo, p.friction->mu);
      hi = std::max(hi, p.friction->mu);
    }
    summary << "  Coulomb friction mu: " << lo << " .. " << hi << " (paper: 0.13 .. 0.33)\n";
    section.numbers["friction_mu_range"] = {lo, hi};
  }
  if (vibration_pairs > 0) {
    const model::io::Pairing* strongest = nullptr;
    const model::io::Pairing* weakest = nullptr;
    for (const auto& p : catalog.pairings) {
      if (!p.vibration) continue;
      if (!strongest || p.vibration->weighted_mean > strongest->vibration->weighted_mean)
        strongest = &p;
      if (!weakest || p.vibration->weighted_mean < weakest->vibration->weighted_mean) weakest = &p;
    }
    summary << "  weighted vibration (mean sensation re threshold): strongest " << strongest->tool
            << " on " << strongest->surface << " (" << strongest->vibration->weighted_mean
            << "), weakest " << weakest->tool << " on " << weakest->surface << " ("
            << weakest->vibration->weighted_mean << ")\n";
    section.numbers["weighted_mean_strongest"] = {{"tool", strongest->tool},
                                                  {"surface", strongest->surface},
                                                  {"value", strongest->vibration->weighted_mean}};
    section.numbers["weighted_mean_weakest"] = {{"tool", weakest->tool},
                                                {"surface", weakest->surface},
                                                {"value", weakest->vibration->weighted_mean}};
  }
  summary << "  threshold curve: " << threshold.source() << "\n"
          << "  source: " << catalog.citation << "\n"
          << "  report: " << output.string()
          << "/ (catalog.json, descriptors.csv, friction.png, spectra/*.png)\n";
  section.text = summary.str();
  return section;
}

// What the demo printed and summed up names its work folder; the user named the report's.
std::string shown_as_report(std::string text, const std::filesystem::path& work,
                            const std::filesystem::path& report) {
  const std::string from = work.string(), to = report.string();
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

void demo(const DemoOptions& named, unsigned threads) {
  constexpr int max_bands = 5;
  // Built beside the folder named and swapped in when whole: a run that fails or is stopped
  // leaves an earlier report as it was.
  model::io::FolderResult result(named.output, "SUMMARY.json");
  DemoOptions options = named;
  options.output = result.work();
  const auto catalog_path =
      options.catalog.empty() ? model::io::default_catalog() : options.catalog;
  const auto threshold = model::measure::ThresholdCurve::load(model::io::default_threshold_curve());
  auto catalog = model::io::read_catalog(catalog_path);
  const std::size_t vibration_pairs =
      model::measure::weigh_catalog_vibration(catalog, threshold, max_bands);

  const auto chosen = [&](const std::string& name) {
    return options.only.empty() ||
           std::find(options.only.begin(), options.only.end(), name) != options.only.end();
  };
  // The mechanics part needs nothing the others make and is mostly FEM solves: it runs beside
  // them (figures are drawn one at a time: ui/report's PlotPage holds PLplot's lock), which
  // shortens the demo on more than one core. Its lines still come second in the summary.
  std::future<DemoSection> mechanics;
  const bool beside = chosen("mechanics") && std::any_of(kSections.begin(), kSections.end(),
                                                         [&](const std::string& name) {
                                                           return name != "mechanics" && chosen(name);
                                                         });
  if (beside)
    mechanics = std::async(std::launch::async, run_mechanics_demo, options.output, false);
  std::map<std::string, DemoSection> sections;
  for (const auto& name : kSections) {
    if (!chosen(name)) continue;
    if (name == "descriptors")
      sections[name] = run_descriptor_demo(catalog, catalog_path, threshold, vibration_pairs, options.output, max_bands);
    else if (name == "mechanics" && !beside)
      sections[name] = run_mechanics_demo(options.output);
    else if (name == "space")
      sections[name] = run_space_demo(catalog, catalog_path, options.output, threads);
    else if (name == "forcing")
      sections[name] = run_forcing_demo(catalog_path, options.output);
    else if (name == "render")
      sections[name] = run_render_demo(catalog, options.catalog, options.output);
    else if (name == "rig")
      sections[name] = run_rig_demo(options.catalog, options.output);
  }
  if (beside) sections["mechanics"] = mechanics.get();
  std::string text;
  nlohmann::json numbers = {{"catalog", catalog_path.string()}, {"sections", nlohmann::json::array()}};
  for (const auto& name : kSections) {
    if (!chosen(name)) continue;
    DemoSection& section = sections.at(name);
    text += section.text;
    numbers["sections"].push_back(name);
    numbers[name] = std::move(section.numbers);
  }
  text = shown_as_report(text, options.output, named.output);
  numbers = nlohmann::json::parse(shown_as_report(numbers.dump(), options.output, named.output));
  write_text_file(options.output / "SUMMARY.txt", text);
  write_json_file(options.output / "SUMMARY.json", numbers);
  result.commit();
  std::cout << text;
}

}  // namespace

void add_demo_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto options = std::make_shared<DemoOptions>();
  auto* cmd =
      app.add_subcommand("demo", "The main job: descriptors and a report from the bundled default");
  cmd->footer(
      "The main job on the bundled default, no hardware or raw data needed: computes the\n"
      "perceptual descriptors of every tool-surface pair in assets/default_catalog.json (spectra\n"
      "and friction derived from the paper's recordings) and writes a report folder with the\n"
      "catalog, a descriptor table, the friction chart and a spectrum figure per pair. Then the\n"
      "mechanics: a cantilever against Euler-Bernoulli under mesh refinement, the paper's bar\n"
      "with a ring-down fit, and the frequency responses of the bundled stylus designs. Last, a\n"
      "perceptual space from a SIMULATED observer (no human judgments of drawing tools are\n"
      "bundled): the two-stage experiment, a fit with bootstrap regions, every tool placed.\n"
      "Then the forcing model of the printed tools with its leave-one-out, a predicted design\n"
      "and a design search in that space (forcing/).\n"
      "Finally every tool with a vibration spectrum is rendered over the rig's sweep through the\n"
      "real-time engine into render/*.wav. SUMMARY.txt says what each part found, and\n"
      "SUMMARY.json holds the same numbers for a script.");
  cmd->add_option("-o,--output", options->output, "Report folder")->capture_default_str();
  cmd->add_option("--catalog", options->catalog, "Use this catalog instead of the bundled one")
      ->check(CLI::ExistingFile);
  cmd->add_option("--only", options->only,
                  "Run only these parts (descriptors, mechanics, space, forcing, render, rig); "
                  "forcing searches a design only in a space the same report holds")
      ->delimiter(',')
      ->check(CLI::IsMember(kSections));
  cmd->callback([options, global] {
    configure_logging(global->verbosity);
    demo(*options, worker_threads(*global));
  });
}

}  // namespace nibrig::ui::cli
