// `nibrig space validate`: k-fold cross-validation for each number of dimensions and λ (Fig. 8),
// and, when the stimulus names carry numbers (Salmon's items are positions on a 1-D continuum), the
// rank correlation of a 1-D fit's coordinate with them.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>

#include "model/space/space_evaluation.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/space_commands.hpp"
#include "ui/cli/space_figures.hpp"

namespace nibrig::ui::cli {

namespace space = model::space;

void run_space_validate(const SpaceValidateOptions& o, unsigned threads) {
  space::DimensionScanOptions scan;
  scan.dims = o.dims;
  scan.lambdas = o.lambdas;
  scan.models.clear();
  for (const auto& name : o.models) {
    if (name == "all") {
      scan.models = space::every_family();
      break;
    }
    scan.models.push_back(space::parse_family(name));
  }
  scan.cross_validation.folds = o.folds;
  scan.cross_validation.seed = o.seed;
  scan.cross_validation.fit.starts = o.starts;
  scan.cross_validation.fit.seed = o.seed;
  scan.cross_validation.fit.threads = threads;
  // The library's bounds, named as the options, before the judgments are read.
  try {
    space::check_dimension_scan(scan, o.descriptors, [](space::SpaceFitField field) {
      return field == space::SpaceFitField::lambda ? std::string("--lambdas")
                                                   : space_fit_option(field);
    });
  } catch (const space::SpaceFitRefused& e) {
    throw CLI::ValidationError(e.what());
  }
  spdlog::info("{}: {}-fold cross-validation of {} spaces", o.judgments.string(), o.folds,
               o.dims.size() * o.lambdas.size() * scan.models.size());
  const space::Validation validation =
      space::validate_space_file(o.judgments, o.descriptors, scan, progress_bar("fitting folds"));
  const std::vector<space::DimensionScanPoint>& points = validation.points;

  nlohmann::json json = {{"judgments", o.judgments.string()},
                         {"folds", o.folds},
                         {"seed", o.seed},
                         {"error_definition",
                          "mean over held-out triplets of |p_predicted - count_a/(count_a+count_b)|"},
                         {"agreement_definition",
                          "a prediction of exactly 0.5 counts as half right; majority agreement "
                          "skips tied triplets"},
                         {"points", nlohmann::json::array()}};
  std::cout << fmt::format("{}-fold cross-validation of {} ({} triplets, {} responses)\n", o.folds,
                           o.judgments.filename().string(), validation.triplets,
                           validation.responses);
  std::cout << " dims  lambda  model                    error (mean ± sd over folds)   majority   individual"
               "   log loss\n";
  for (const auto& p : points) {
    std::cout << fmt::format("  {:>2}  {:>6.3g}  {:<24} {:5.1f} % ± {:4.1f} %             {:5.1f} %    "
                             "{:5.1f} %     {:.4f}\n",
                             p.dims, p.lambda, space::family_name(p.model), 100 * p.mean_error, 100 * p.sd_error,
                             100 * p.majority_agreement, 100 * p.individual_agreement, p.log_loss);
    json["points"].push_back({{"dims", p.dims},
                              {"lambda", p.lambda},
                              {"model", space::family_name(p.model)},
                              {"log_loss", p.log_loss},
                              {"mean_error", p.mean_error},
                              {"sd_error", p.sd_error},
                              {"majority_agreement", p.majority_agreement},
                              {"individual_agreement", p.individual_agreement}});
  }

  if (const auto& rho = validation.rank_correlation_with_names) {
    std::cout << fmt::format(
        "1-D fit of all judgments vs the number in each stimulus name: Spearman rho = {:+.3f} "
        "(p = {:.2g}, {} stimuli)\n",
        rho->r, rho->p_value, rho->n);
    json["rank_correlation_with_names"] = {{"rho", rho->r}, {"p_value", rho->p_value}, {"n", rho->n}};
  }
  if (!o.output.empty()) {
    write_json_file(o.output, json);
    say_wrote(o.output);
  }
  if (!o.plots.empty()) {
    ensure_folder(o.plots);
    write_dimension_scan_plot(points, "Cross-validated error of " + o.judgments.filename().string(),
                              o.plots / "dimension_scan.png");
    say_wrote(o.plots / "dimension_scan.png");
  }
}

}  // namespace nibrig::ui::cli
