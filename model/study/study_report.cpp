#include "model/study/study_report.hpp"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/measure/order_statistics.hpp"
#include "model/space/objective.hpp"
#include "model/space/space_file.hpp"
#include "model/space/space_inputs.hpp"
#include "model/io/finite_output.hpp"

namespace nibrig::model::study {
namespace {

// The probability that each response's left stimulus is chosen under a space whose stimuli are
// named (a fitted space numbers them in the order the judgments file first names them).
class SpacePredictor {
 public:
  SpacePredictor(const space::SpaceFile& space, const std::vector<std::string>& study_names)
      : space_(space) {
    std::map<std::string, Eigen::Index> column;
    for (std::size_t i = 0; i < space.stimuli.size(); ++i)
      column[space.stimuli[i]] = static_cast<Eigen::Index>(i);
    for (const auto& name : study_names) {
      const auto it = column.find(name);
      columns_.push_back(it == column.end() ? -1 : it->second);
    }
  }
  // nullopt when the space lacks one of the three (a stimulus no participant's answer reached).
  std::optional<double> p_left(const space::Trial& t) const {
    const Eigen::Index r = columns_[t.reference], a = columns_[t.left], b = columns_[t.right];
    if (r < 0 || a < 0 || b < 0) return std::nullopt;
    return space::probability_first(space_.model, space_.coordinates, static_cast<std::size_t>(r),
                                    static_cast<std::size_t>(a), static_cast<std::size_t>(b));
  }

 private:
  const space::SpaceFile& space_;
  std::vector<Eigen::Index> columns_;
};

ParticipantSummary summarise(const StudyData& study, const ParticipantData& p,
                             const SpacePredictor& predictor) {
  ParticipantSummary s;
  s.id = p.record.id;
  s.respondent = p.record.respondent;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, io::Triplet> others;
  for (const auto& t : pooled_counts(study, p.record.id)) others[{t.reference, t.a, t.b}] = t;
  std::vector<double> times;
  double with_space = 0.0, scored = 0.0, with_others = 0.0, compared = 0.0;
  for (const auto& r : p.responses) {
    if (r.practice) {
      ++s.practice;
      continue;
    }
    ++s.answers;
    times.push_back(r.response_s);
    const bool left = r.chosen == space::Choice::left;
    if (const auto p_left = predictor.p_left(r.planned)) {
      scored += 1.0;
      with_space += *p_left == 0.5 ? 0.5 : ((*p_left > 0.5) == left ? 1.0 : 0.0);
    }
    const std::size_t a = std::min(r.planned.left, r.planned.right);
    const std::size_t b = std::max(r.planned.left, r.planned.right);
    const auto it = others.find({r.planned.reference, a, b});
    if (it == others.end()) continue;
    const std::size_t chosen = left ? r.planned.left : r.planned.right;
    const int for_chosen = chosen == a ? it->second.count_a : it->second.count_b;
    const int against = chosen == a ? it->second.count_b : it->second.count_a;
    compared += 1.0;
    with_others += for_chosen == against ? 0.5 : (for_chosen > against ? 1.0 : 0.0);
  }
  s.median_response_s = times.empty() ? 0.0 : measure::median(times);
  s.with_space = space::agreement_test(with_space, scored);
  if (compared > 0) s.with_others = space::agreement_test(with_others, compared);
  return s;
}

nlohmann::json agreement_json(const space::AgreementTest& t) {
  return {{"agreements", t.agreements}, {"trials", t.trials}, {"fraction", t.fraction},
          {"z", t.z},                   {"p_value", t.p_value}};
}

// Every stimulus is a catalog pairing with descriptors: then the fit ties its axes to them and
// the space can place other tools.
bool all_catalog_pairings(const StudyDefinition& d, const std::filesystem::path& catalog_file) {
  const io::Catalog catalog = io::read_catalog(catalog_file);
  for (const auto& s : d.stimuli) {
    if (s.name != pairing_of(s)) return false;
    const bool found = std::any_of(catalog.pairings.begin(), catalog.pairings.end(),
                                   [&](const io::Pairing& p) {
                                     return p.tool == s.tool && p.surface == s.surface &&
                                            p.vibration && p.friction;
                                   });
    if (!found) return false;
  }
  return true;
}

void write_report_json(const StudyReport& r, const std::filesystem::path& file) {
  const StudyDefinition& d = r.study.definition;
  nlohmann::json j;
  j["format"] = "nibrig-study-report";
  j["version"] = 1;
  j["study"] = r.study.folder.string();
  j["mode"] = mode_name(d.mode);
  j["plan"] = plan_name(d.plan);
  j["stimuli"] = d.stimuli.size();
  j["selection"] = r.selection == JudgmentSelection::paper ? "paper" : "every answer";
  j["triplets"] = r.judgments.triplets.size();
  j["responses"] = io::response_count(r.judgments);
  if (r.fitted) {
    j["space"] = {{"dims", r.fitted->file.coordinates.rows()},
                  {"objective", r.fitted->file.objective},
                  {"with_descriptors", r.with_descriptors},
                  {"bootstrap_resamples", r.fitted->file.bootstrap_resamples},
                  {"mean_region_sd", r.fitted->mean_region_sd}};
  }
  nlohmann::json people = nlohmann::json::array();
  for (const auto& p : r.participants) {
    nlohmann::json one = {{"id", p.id},
                          {"respondent", p.respondent},
                          {"answers", p.answers},
                          {"practice", p.practice},
                          {"median_response_s", p.median_response_s},
                          {"agreement_with_space", agreement_json(p.with_space)}};
    one["agreement_with_others"] = p.with_others ? agreement_json(*p.with_others) : nlohmann::json();
    people.push_back(one);
  }
  j["participants"] = people;
  if (r.validation) {
    const auto& v = *r.validation;
    nlohmann::json triplets = nlohmann::json::array();
    for (std::size_t i = 0; i < r.validation_triplets.size(); ++i) {
      const auto& t = r.validation_triplets[i];
      triplets.push_back({{"reference", d.stimuli[t.reference].name},
                          {"a", d.stimuli[t.a].name},
                          {"b", d.stimuli[t.b].name},
                          {"count_a", t.count_a},
                          {"count_b", t.count_b},
                          {"predicted_p_a", r.validation_predicted[i]}});
    }
    j["validation"] = {{"space", r.validation_space.string()},
                       {"triplets", triplets},
                       {"majority_agreement", agreement_json(v.majority)},
                       {"individual_agreement", agreement_json(v.individual)},
                       {"mean_absolute_error", v.mean_absolute_error}};
    if (v.probability_correlation)
      j["validation"]["pearson"] = {{"r", v.probability_correlation->r},
                                    {"p_value", v.probability_correlation->p_value}};
    else
      j["validation"]["pearson_missing_because"] = v.no_correlation_because;
  }
  j["warnings"] = r.warnings;
  io::write_file_atomically(file, io::json_text(j, file));
}

}  // namespace

StudyReport report_study(const std::filesystem::path& study_folder,
                         const std::filesystem::path& report_folder,
                         const StudyReportSettings& settings) {
  StudyReport report;
  report.study = read_study(study_folder);
  const StudyDefinition& d = report.study.definition;
  report.warnings = report.study.warnings;
  report.selection = settings.selection.value_or(default_selection(d));
  report.judgments = study_judgments(report.study, report.selection);
  if (report.judgments.triplets.empty())
    throw std::invalid_argument(study_folder.string() + ": no participant has answered a trial " +
                                "of the study yet (practice is not counted)");
  // The space is read before anything is written: it may lie in the report's folder.
  std::optional<space::SpaceFile> scored_against;
  if (d.mode == StudyMode::validation) {
    if (settings.validation_space.empty())
      throw std::invalid_argument(
          "a validation study is scored against a perceptual space: give the space it tests");
    scored_against = space::read_space_file(settings.validation_space);
  } else if (!settings.validation_space.empty()) {
    throw std::invalid_argument(settings.validation_space.string() +
                                ": a space scores a validation study only; the study in " +
                                study_folder.string() + " is not one (its space is fitted to its answers)");
  }
  std::filesystem::create_directories(report_folder);
  const std::filesystem::path judgments_file = report_folder / kReportJudgments;
  io::write_triplet_csv(judgments_file, report.judgments);
  std::vector<std::string> names;
  for (const auto& s : d.stimuli) names.push_back(s.name);
  const std::filesystem::path catalog = io::or_default(settings.catalog, io::default_catalog);

  if (d.mode == StudyMode::validation) {
    report.validation_space = settings.validation_space;
    const space::SpaceFile& s = *scored_against;
    space::StimulusLocator locator(s, settings.validation_space,
                                   s.descriptor_map ? catalog : std::filesystem::path{});
    io::TripletSet pooled;
    pooled.stimuli = names;
    pooled.triplets = pooled_counts(report.study);
    // Stimuli are looked up by name: a judged one of the space, else as "tool/surface" from its
    // descriptors.
    for (std::size_t i = 0; i < d.stimuli.size(); ++i)
      if (std::find(s.stimuli.begin(), s.stimuli.end(), names[i]) == s.stimuli.end())
        pooled.stimuli[i] = pairing_of(d.stimuli[i]);
    const auto predictions =
        space::predict_queries(s, pooled, locator, study_folder / kStudyFile);
    for (const auto& q : predictions) report.validation_predicted.push_back(q.p);
    report.validation_triplets = pooled.triplets;
    report.validation = space::score_predictions(report.validation_predicted, pooled.triplets);
    // The participants are scored against the same space, the validated one, by name.
    space::SpaceFile renamed = s;
    Eigen::MatrixXd placed(s.coordinates.rows(), static_cast<Eigen::Index>(names.size()));
    for (std::size_t i = 0; i < names.size(); ++i)
      placed.col(static_cast<Eigen::Index>(i)) = locator.locate(pooled.stimuli[i], study_folder).mean;
    renamed.stimuli = names;
    renamed.coordinates = placed;
    scored_against = renamed;
  } else {
    report.with_descriptors = all_catalog_pairings(d, catalog);
    const std::filesystem::path descriptors = report.with_descriptors ? catalog : std::filesystem::path{};
    if (!report.with_descriptors)
      report.warnings.push_back(
          "not every stimulus is a catalog pairing with friction and vibration: the space is "
          "fitted without descriptors (it cannot place other tools)");
    const space::SpaceInputs inputs = space::read_space_inputs(judgments_file, descriptors, d.dims, 0.0);
    space::SpaceFitSettings fit;
    fit.starts = settings.starts;
    fit.seed = settings.seed;
    fit.threads = settings.threads;
    fit.bootstrap = settings.bootstrap;
    fit.stop = settings.stop;
    report.fitted = space::fit_space_file(inputs, judgments_file, descriptors, fit, settings.progress);
    report.warnings.insert(report.warnings.end(), report.fitted->warnings.begin(),
                           report.fitted->warnings.end());
    space::write_space_file(report_folder / kReportSpace, report.fitted->file);
    scored_against = report.fitted->file;
  }
  const SpacePredictor predictor(*scored_against, names);
  for (const auto& p : report.study.participants) {
    if (!has_main_answers(p)) {
      report.warnings.push_back("participant " + p.record.id + ": no answer to a main trial yet (" +
                                std::to_string(p.responses.size()) + " practice); not counted");
      continue;
    }
    report.participants.push_back(summarise(report.study, p, predictor));
  }
  write_report_json(report, report_folder / kReportStatistics);
  return report;
}

}  // namespace nibrig::model::study
