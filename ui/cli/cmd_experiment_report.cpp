// `nibrig experiment report`: what model::study::report_study computes, on the terminal and as
// figures: the fitted space with its regions, each participant's agreement with the space and with
// the others, and for a validation study each triplet's observed preference beside the space's
// prediction (the paper's Fig. 16).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <iostream>

#include "model/study/study_report.hpp"
#include "ui/cli/experiment_commands.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/space_figures.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::cli {
namespace {

namespace study = model::study;

// A share of n answers with its 95 % Wilson interval, in percent: unlike the normal
// approximation it does not shrink to nothing when every answer agrees (5 of 5 is not certainty).
report::IntervalBar share_bar(const std::string& label, double agreements, double n,
                              const std::string& group) {
  const double f = n > 0 ? agreements / n : 0.0;
  if (n <= 0) return {label, 0.0, 0.0, 0.0, group};
  const double z2 = 1.96 * 1.96;
  const double centre = (f + z2 / (2 * n)) / (1 + z2 / n);
  const double half = 1.96 * std::sqrt(f * (1 - f) / n + z2 / (4 * n * n)) / (1 + z2 / n);
  return {label, 100 * f, 100 * std::max(0.0, centre - half), 100 * std::min(1.0, centre + half),
          group};
}

void write_agreement_chart(const study::StudyReport& r, const std::filesystem::path& png) {
  report::IntervalChart chart;
  chart.title = "Agreement of each participant's answers (95 % intervals; chance is 50 %)";
  chart.value_label = "answers agreeing (%)";
  for (const auto& p : r.participants) {
    chart.bars.push_back(share_bar(p.id, p.with_space.agreements, p.with_space.trials,
                                   "with the space's prediction"));
    if (p.with_others)
      chart.bars.push_back(share_bar(p.id, p.with_others->agreements, p.with_others->trials,
                                     "with the other participants' majority"));
  }
  report::write_interval_chart(chart, png);
}

void write_validation_chart(const study::StudyReport& r, const std::filesystem::path& png) {
  report::IntervalChart chart;
  chart.title = "Validation (Sec. 6.1) against " + r.study.definition.stimuli.front().name +
                ": preference for the first candidate, observed (95 %) and predicted";
  chart.value_label = "P(first candidate chosen) (%)";
  const auto& d = r.study.definition;
  for (std::size_t i = 0; i < r.validation_triplets.size(); ++i) {
    const auto& t = r.validation_triplets[i];
    const std::string label = d.stimuli[t.a].name + " vs " + d.stimuli[t.b].name;
    chart.bars.push_back(share_bar(label, t.count_a, t.count_a + t.count_b, "observed"));
    const double p = 100 * r.validation_predicted[i];
    chart.bars.push_back({label, p, p, p, "predicted by the space"});
  }
  report::write_interval_chart(chart, png);
}

std::string agreement_text(const model::space::AgreementTest& t) {
  return fmt::format("{:.1f} % of {:.0f} (z = {:.2f}, p = {:.2g})", 100 * t.fraction, t.trials, t.z,
                     t.p_value);
}

}  // namespace

void run_experiment_report(const ExperimentReportOptions& o, unsigned threads) {
  study::StudyReportSettings settings;
  if (o.all_judgments) settings.selection = study::JudgmentSelection::every_answer;
  settings.starts = o.starts;
  settings.bootstrap = o.bootstrap;
  settings.seed = o.seed;
  settings.threads = threads;
  settings.catalog = o.catalog;
  settings.validation_space = o.space;
  std::string step_shown;
  std::function<void(std::size_t, std::size_t)> bar;
  settings.progress = [&](const std::string& step, std::size_t done, std::size_t total) {
    if (step != step_shown) bar = progress_bar(step), step_shown = step;
    if (bar) bar(done, total);
  };
  const std::filesystem::path folder = o.output.empty() ? o.study / "report" : o.output;
  const study::StudyReport r = study::report_study(o.study, folder, settings);
  for (const auto& w : r.warnings) spdlog::warn("{}", w);
  const auto& d = r.study.definition;
  std::cout << fmt::format("{}: {} mode, {} plan, {} stimuli, participants: {}; {} triplets with {} "
                           "answers ({})\n",
                           o.study.string(), study::mode_name(d.mode), study::plan_name(d.plan),
                           d.stimuli.size(), r.participants.size(), r.judgments.triplets.size(),
                           model::io::response_count(r.judgments),
                           r.selection == study::JudgmentSelection::paper
                               ? "the paper's selection: stage 2 and the stage-1 triplets that "
                                 "were not ties"
                               : "every answer");
  say_wrote(folder / study::kReportJudgments);
  if (r.fitted) {
    const auto& f = *r.fitted;
    std::cout << fmt::format("fitted {}-D space{}: -log likelihood {:.2f} over {} responses",
                             f.file.coordinates.rows(),
                             r.with_descriptors ? " tied to the catalog's descriptors" : "",
                             f.fit.negative_log_likelihood, f.file.responses);
    if (f.file.bootstrap_resamples > 0)
      std::cout << fmt::format("; {} bootstrap refits, mean per-axis sd of a stimulus {:.3f}",
                               f.file.bootstrap_resamples, f.mean_region_sd);
    std::cout << "\n";
    say_wrote(folder / study::kReportSpace);
    write_space_plot(f.file, {}, "Perceptual space of " + o.study.filename().string(),
                     folder / "space.png");
    say_wrote(folder / "space.png");
  }
  std::cout << "participant  answers  median time  agreement with the space / with the others\n";
  for (const auto& p : r.participants)
    std::cout << fmt::format("{:<12} {:>7}  {:>9.1f} s  {} / {}\n", p.id, p.answers,
                             p.median_response_s, agreement_text(p.with_space),
                             p.with_others ? agreement_text(*p.with_others) : "nobody else");
  if (r.validation) {
    const auto& v = *r.validation;
    std::cout << fmt::format("validation against {}: majority agreement {}; individual {}; mean "
                             "error of the predicted preference {:.1f} %",
                             o.space.string(), agreement_text(v.majority),
                             agreement_text(v.individual), 100 * v.mean_absolute_error);
    if (v.probability_correlation)
      std::cout << fmt::format("; Pearson r = {:.2f} (p = {:.2g})", v.probability_correlation->r,
                               v.probability_correlation->p_value);
    else
      std::cout << "; no correlation: " << v.no_correlation_because;
    std::cout << "\n";
    write_validation_chart(r, folder / "validation.png");
    say_wrote(folder / "validation.png");
  }
  write_agreement_chart(r, folder / "agreement.png");
  say_wrote(folder / "agreement.png");
  say_wrote(folder / study::kReportStatistics);
}

}  // namespace nibrig::ui::cli
