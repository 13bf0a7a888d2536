// `nibrig space fit`: judgments (and descriptors) → space.json with fit statistics, the descriptor
// map and, on request, bootstrap confidence regions.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <iostream>

#include "model/space/bootstrap.hpp"
#include "model/space/fit.hpp"
#include "model/space/space_file.hpp"
#include "model/space/statistics.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/space_commands.hpp"
#include "ui/cli/space_figures.hpp"
#include "model/space/space_inputs.hpp"

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

}  // namespace

void run_space_fit(const SpaceFitOptions& o, unsigned threads) {
  const model::space::SpaceInputs in = model::space::read_space_inputs(o.judgments, o.descriptors, o.dims, o.lambda);
  space::FitOptions options;
  options.starts = o.starts;
  options.seed = o.seed;
  options.threads = threads;
  spdlog::info("{}: {} stimuli, {} triplets, {} responses; {}-D fit from {} starts, lambda {}",
               o.judgments.string(), in.judgments.stimuli.size(), in.judgments.triplets.size(),
               model::io::response_count(in.judgments), o.dims, o.starts, o.lambda);
  const auto start = std::chrono::steady_clock::now();
  const space::FitResult fit =
      space::fit_space(in.problem, options, progress_bar("fitting starts"));
  space::SpaceFile file;
  file.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  file.stimuli = in.judgments.stimuli;
  file.coordinates = fit.coordinates;
  file.scale = in.problem.scale;
  file.lambda = in.problem.lambda;
  file.objective = fit.objective;
  file.negative_log_likelihood = fit.negative_log_likelihood;
  file.start_objectives = fit.start_objectives;
  file.triplets = in.judgments.triplets.size();
  file.responses = model::io::response_count(in.judgments);
  file.judgments = o.judgments.string();
  if (in.descriptors) {
    file.descriptor_names = in.descriptors->names;
    file.descriptors = in.descriptors->values;
    file.descriptor_source = o.descriptors.string();
    if (file.stimuli.size() > file.descriptor_names.size() + 1)
      file.descriptor_map =
          space::fit_descriptor_map(fit.coordinates, file.descriptors, file.descriptor_names);
    else
      spdlog::warn("{} stimuli are too few to learn a map from {} descriptors; no tool can be "
                   "placed from descriptors with this space",
                   file.stimuli.size(), file.descriptor_names.size());
  }
  std::cout << fmt::format(
      "fitted {}-D space of {} stimuli in {:.2f} s: -log likelihood {:.2f} per {} responses; best "
      "of {} starts, worst start {:.2f}\n",
      o.dims, file.stimuli.size(), file.seconds, fit.negative_log_likelihood, file.responses,
      o.starts, fit.start_objectives.back());
  if (in.descriptors) report_axis_correlations(file);
  if (file.descriptor_map)
    for (std::size_t d = 0; d < file.descriptor_map->r_squared.size(); ++d)
      std::cout << fmt::format("  descriptor map, axis {}: R^2 = {:.3f}\n", d + 1,
                               file.descriptor_map->r_squared[d]);
  if (o.bootstrap > 0) {
    space::BootstrapOptions b;
    b.resamples = o.bootstrap;
    b.seed = o.seed;
    b.threads = threads;
    const auto b_start = std::chrono::steady_clock::now();
    const space::BootstrapResult regions =
        space::bootstrap_space(in.problem, fit.coordinates, b, progress_bar("bootstrap refits"));
    file.regions = regions.regions;
    file.region_levels = regions.levels;
    file.bootstrap_resamples = o.bootstrap;
    std::cout << fmt::format(
        "bootstrap: {} refits in {:.1f} s; mean per-axis sd of a stimulus {:.3f} units\n",
        o.bootstrap,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - b_start).count(),
        space::mean_per_axis_sd(regions));
  }
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
