// `nibrig space fit`: judgments (and descriptors) → space.json with fit statistics, the descriptor
// map and, on request, bootstrap confidence regions.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <iostream>

#include "model/space/space_file.hpp"
#include "model/space/space_fit_file.hpp"
#include "model/space/space_fit_request.hpp"
#include "model/space/space_inputs.hpp"
#include "model/space/statistics.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/space_commands.hpp"
#include "ui/cli/space_figures.hpp"

namespace nibrig::ui::cli {

namespace space = model::space;

namespace {

// |r| between axis d and descriptor d, the quantity the correlation term maximises.
void report_axis_correlations(const space::SpaceFile& file) {
  for (Eigen::Index d = 0; d < file.coordinates.rows() && d < file.descriptors.cols(); ++d) {
    const Eigen::VectorXd q = file.coordinates.row(d).transpose();
    const Eigen::VectorXd x = file.descriptors.col(d);
    const auto c = space::pearson({q.data(), q.data() + q.size()}, {x.data(), x.data() + x.size()});
    std::cout << fmt::format("  axis {} vs {}: r = {:+.3f} (p = {:.2g})\n", d + 1,
                             file.descriptor_names[static_cast<std::size_t>(d)], c.r, c.p_value);
  }
}

// Which judgment model, with its fitted parts, and the cross-validation that chose it.
void report_model(const space::SpaceFile& file) {
  std::cout << fmt::format("judgment model {}: {}\n", space::describe_model(file.model), file.model_reason);
  if (file.model_scores.empty()) return;
  std::cout << "  model                    held-out log loss   majority   individual   error\n";
  for (const auto& s : file.model_scores)
    std::cout << fmt::format("  {:<24} {:>8.4f}           {:5.1f} %    {:5.1f} %     {:5.1f} %{}\n", s.family,
                             s.log_loss, 100 * s.majority_agreement, 100 * s.individual_agreement, 100 * s.mean_error,
                             s.family == space::family_name(file.model.family) ? "  <- chosen" : "");
}

}  // namespace

std::string space_fit_option(space::SpaceFitField field) {
  using Field = space::SpaceFitField;
  switch (field) {
    case Field::dims:
      return "--dims";
    case Field::lambda:
      return "--lambda";
    case Field::descriptors:
      return "--descriptors";
    case Field::starts:
      return "--starts";
    case Field::bootstrap:
      return "--bootstrap";
    case Field::folds:
      return "--folds";
    case Field::models:
      return "--models";
  }
  return space::field_name(field);
}

void run_space_fit(const SpaceFitOptions& o, unsigned threads) {
  space::SpaceFitRequest request;
  request.dims = o.dims;
  request.lambda = o.lambda;
  request.descriptors = o.descriptors;
  auto& settings = request.settings;
  settings.starts = o.starts;
  settings.seed = o.seed;
  settings.threads = threads;
  settings.bootstrap = o.bootstrap;
  settings.choose_model = o.model == "auto";
  if (!settings.choose_model) settings.model = space::parse_family(o.model);
  request.candidates_listed = !o.models.empty();
  if (!o.models.empty()) {
    settings.candidates.clear();
    for (const auto& name : o.models) settings.candidates.push_back(space::parse_family(name));
  }
  settings.folds = o.folds;
  // The library's bounds, named as the options, before the judgments are read.
  try {
    space::check_space_fit(request, space_fit_option);
  } catch (const space::SpaceFitRefused& e) {
    throw CLI::ValidationError(e.what());
  }
  const model::space::SpaceInputs in =
      model::space::read_space_inputs(o.judgments, o.descriptors, o.dims, o.lambda);
  spdlog::info("{}: {} stimuli, {} triplets, {} responses; {}-D fit from {} starts, lambda {}",
               o.judgments.string(), in.judgments.stimuli.size(), in.judgments.triplets.size(),
               model::io::response_count(in.judgments), o.dims, o.starts, o.lambda);
  // One bar a step: the starts, then the bootstrap's refits.
  std::string step_shown;
  std::function<void(std::size_t, std::size_t)> bar;
  const auto fitted = space::fit_space_file(
      in, o.judgments, o.descriptors, settings,
      [&](const std::string& step, std::size_t done, std::size_t total) {
        if (step != step_shown) bar = progress_bar(step), step_shown = step;
        if (bar) bar(done, total);
      });
  const space::SpaceFile& file = fitted.file;
  for (const auto& w : fitted.warnings) spdlog::warn("{}", w);
  std::cout << fmt::format(
      "fitted {}-D space of {} stimuli in {:.2f} s: -log likelihood {:.2f} per {} responses; best "
      "of {} starts, worst start {:.2f}\n",
      o.dims, file.stimuli.size(), file.seconds, fitted.fit.negative_log_likelihood, file.responses,
      o.starts, fitted.fit.start_objectives.back());
  report_model(file);
  if (in.descriptors) report_axis_correlations(file);
  if (file.descriptor_map)
    for (std::size_t d = 0; d < file.descriptor_map->r_squared.size(); ++d)
      std::cout << fmt::format("  descriptor map, axis {}: R^2 = {:.3f}\n", d + 1,
                               file.descriptor_map->r_squared[d]);
  if (o.bootstrap > 0)
    std::cout << fmt::format("bootstrap: {} refits in {:.1f} s; mean per-axis sd of a stimulus {:.3f} units\n",
                             o.bootstrap, fitted.bootstrap_seconds, fitted.mean_region_sd);
  ensure_folder(o.output.parent_path());
  space::write_space_file(o.output, file);
  say_wrote(o.output);
  if (!o.plot.empty()) {
    ensure_folder(o.plot.parent_path());
    write_space_plot(file, {}, "Perceptual space of " + o.judgments.filename().string(), o.plot);
    say_wrote(o.plot);
  }
}

}  // namespace nibrig::ui::cli
