// `nibrig space validate`: k-fold cross-validation for each number of dimensions and λ (Fig. 8),
// and, when the stimulus names carry numbers (Salmon's items are positions on a 1-D continuum), the
// rank correlation of a 1-D fit's coordinate with them.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <regex>

#include "model/space/dimension_sweep.hpp"
#include "model/space/statistics.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/space_commands.hpp"
#include "ui/cli/space_figures.hpp"
#include "model/space/space_inputs.hpp"

namespace nibrig::ui::cli {

namespace space = model::space;

namespace {

// The trailing number of every name ("i0464" → 464), or nothing when any name has none.
std::optional<std::vector<double>> numbers_in_names(const std::vector<std::string>& names) {
  static const std::regex trailing_number("([0-9]+)$");
  std::vector<double> numbers;
  for (const auto& n : names) {
    std::smatch m;
    if (!std::regex_search(n, m, trailing_number)) return std::nullopt;
    numbers.push_back(std::stod(m[1].str()));
  }
  return numbers;
}

}  // namespace

void run_space_validate(const SpaceValidateOptions& o, unsigned threads) {
  const double max_lambda = *std::max_element(o.lambdas.begin(), o.lambdas.end());
  const std::size_t max_dims = *std::max_element(o.dims.begin(), o.dims.end());
  // An option missing is a usage error, found before the judgments are read.
  if (max_lambda > 0 && o.descriptors.empty())
    throw CLI::ValidationError("--lambdas", "above 0 need --descriptors catalog.json");
  const model::space::SpaceInputs in = model::space::read_space_inputs(o.judgments, {}, max_dims, 0.0);
  std::optional<model::io::Catalog> catalog;
  if (!o.descriptors.empty()) catalog = model::io::read_catalog(o.descriptors);
  std::function<Eigen::MatrixXd(std::size_t)> descriptors;
  if (catalog)
    descriptors = [&](std::size_t dims) {
      return space::descriptors_for_stimuli(*catalog, o.descriptors, in.judgments.stimuli, dims)
          .values;
    };
  space::SweepOptions sweep;
  sweep.dims = o.dims;
  sweep.lambdas = o.lambdas;
  sweep.models.clear();
  for (const auto& name : o.models) {
    if (name == "all") {
      sweep.models = space::every_family();
      break;
    }
    sweep.models.push_back(space::parse_family(name));
  }
  sweep.cross_validation.folds = o.folds;
  sweep.cross_validation.seed = o.seed;
  sweep.cross_validation.fit.starts = o.starts;
  sweep.cross_validation.fit.seed = o.seed;
  sweep.cross_validation.fit.threads = threads;
  spdlog::info("{}: {} stimuli, {} triplets; {}-fold cross-validation of {} spaces",
               o.judgments.string(), in.problem.stimuli, in.problem.triplets.size(), o.folds,
               o.dims.size() * o.lambdas.size() * sweep.models.size());
  const std::vector<space::SweepPoint> points =
      space::sweep_dimensions(in.problem, descriptors, sweep, progress_bar("fitting folds"));

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
                           o.judgments.filename().string(), in.problem.triplets.size(),
                           model::io::response_count(in.judgments));
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

  const auto numbers = numbers_in_names(in.judgments.stimuli);
  if (numbers && std::find(o.dims.begin(), o.dims.end(), 1u) != o.dims.end()) {
    space::SpaceProblem one = in.problem;
    one.dims = 1;
    space::FitOptions fit = sweep.cross_validation.fit;
    const Eigen::MatrixXd q = space::fit_space(one, fit).coordinates;
    const auto rho = space::spearman({q.data(), q.data() + q.size()}, *numbers);
    std::cout << fmt::format(
        "1-D fit of all judgments vs the number in each stimulus name: Spearman rho = {:+.3f} "
        "(p = {:.2g}, {} stimuli)\n",
        rho.r, rho.p_value, rho.n);
    json["rank_correlation_with_names"] = {{"rho", rho.r}, {"p_value", rho.p_value}, {"n", rho.n}};
  }
  if (!o.output.empty()) {
    write_json_file(o.output, json);
    say_wrote(o.output);
  }
  if (!o.plots.empty()) {
    ensure_folder(o.plots);
    write_sweep_plot(points, "Cross-validated error of " + o.judgments.filename().string(),
                     o.plots / "dimension_sweep.png");
    say_wrote(o.plots / "dimension_sweep.png");
  }
}

}  // namespace nibrig::ui::cli
