#include "ui/cli/demo_space.hpp"

#include <fmt/format.h>

#include <functional>
#include <map>
#include <memory>

#include "model/io/triplets.hpp"
#include "model/space/simulated_study.hpp"
#include "model/space/space_file.hpp"
#include "model/space/space_tools.hpp"
#include "model/space/synthetic_study.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/space_figures.hpp"

namespace nibrig::ui::cli {

namespace space = model::space;

DemoSection run_space_demo(const model::io::Catalog& catalog,
                           const std::filesystem::path& catalog_file,
                           const std::filesystem::path& report, unsigned threads) {
  const auto dir = report / "space";
  ensure_folder(dir);
  space::SimulatedStudyOptions options;
  // Named beside space.json, not by its path: the report is built in a work folder and then moved.
  options.judgments_file = "judgments.csv (beside this file)";
  options.threads = threads;
  // One bar per step; each step's bar ends its line with the step's last unit.
  auto bars = std::make_shared<std::map<std::string, std::function<void(std::size_t, std::size_t)>>>();
  options.progress = [bars](const std::string& step, std::size_t done, std::size_t total) {
    auto& bar = (*bars)[step];
    if (!bar) bar = progress_bar(step);
    if (done > 0) bar(done, total);
  };
  const space::SimulatedStudy study = space::run_simulated_study(catalog, catalog_file, options);
  const space::SpaceFile& file = study.space;
  // The trial lists a real experiment would produce, and every answer merged as the fit saw it.
  space::write_trial_csv(dir / "stage1_trials.csv", study.stage_one);
  space::write_trial_csv(dir / "stage2_trials.csv", study.stage_two);
  model::io::write_triplet_csv(dir / "judgments.csv", study.judgments);
  space::write_space_file(dir / "space.json", file);

  const auto points = space::scan_simulated_study(study, catalog, catalog_file, options);
  write_dimension_scan_plot(points, "SIMULATED observer: cross-validated error",
                            dir / "dimension_scan.png");

  // Every other catalog pairing placed from its descriptors (Fig. 15).
  std::vector<PlacedTool> placed;
  for (const auto& p : space::place_catalog(file, catalog, catalog_file))
    if (!p.judged) placed.push_back({p.pairing, p.placement, "", true});
  write_space_plot(file, {}, "Perceptual space of a SIMULATED observer (2-D, 68/95 % bootstrap)",
                   dir / "space.png");
  write_space_plot(file, placed, "SIMULATED observer: every catalog tool placed from descriptors",
                   dir / "placed_tools.png");

  const space::RecoveryError recovery = space::recovery_error(study.fit.coordinates, study.truth);
  const space::DimensionScanPoint* best = &points.front();
  for (const auto& p : points)
    if (p.mean_error < best->mean_error) best = &p;
  DemoSection section;
  section.numbers = {
      {"simulated_observer", true},
      {"stimuli", file.stimuli.size()},
      {"stage1_trials", study.stage_one.trials.size()},
      {"stage2_trials", study.stage_two.trials.size()},
      {"stage1_ties", study.ties},
      {"judgments", study.judgments.triplets.size()},
      {"dims", file.coordinates.rows()},
      {"lambda", options.lambda},
      {"negative_log_likelihood", study.fit.negative_log_likelihood},
      {"recovery_probability_error", recovery.probabilities},
      {"recovery_coordinate_error", recovery.coordinates},
      {"best_cross_validated",
       {{"dims", best->dims},
        {"lambda", best->lambda},
        {"held_out_error", best->mean_error},
        {"majority_agreement", best->majority_agreement}}},
      {"bootstrap_resamples", options.bootstrap_resamples},
      {"regions", file.regions.size()},
      {"descriptor_map_r_squared", file.descriptor_map->r_squared},
      {"placed_tools", placed.size()}};
  section.text = fmt::format(
      "perceptual space (SIMULATED observer: no human judgments of drawing tools are bundled)\n"
      "  an observer whose perception is the catalog's descriptors judged the paper's two-stage\n"
      "  experiment on {} tool/surface pairs: {} + {} trials, {} stage-1 ties\n"
      "  2-D fit (lambda {}): -log likelihood {:.1f}; recovery of the simulated truth: "
      "probability\n"
      "  error {:.1f} %, coordinate error {:.1f} % of its spread\n"
      "  5-fold cross-validation, best: {}-D lambda {} with {:.1f} % held-out error, {:.1f} % "
      "majority "
      "agreement\n"
      "  {} bootstrap refits; descriptor map R^2 {:.2f} / {:.2f}; {} further tools placed\n"
      "  report: {}/ (space.json, judgments.csv, stage*_trials.csv, space.png, placed_tools.png,\n"
      "  dimension_scan.png)\n",
      file.stimuli.size(), study.stage_one.trials.size(), study.stage_two.trials.size(), study.ties,
      options.lambda, study.fit.negative_log_likelihood, 100 * recovery.probabilities,
      100 * recovery.coordinates, best->dims, best->lambda, 100 * best->mean_error,
      100 * best->majority_agreement, options.bootstrap_resamples,
      file.descriptor_map->r_squared[0], file.descriptor_map->r_squared[1], placed.size(),
      dir.string());
  return section;
}

}  // namespace nibrig::ui::cli
