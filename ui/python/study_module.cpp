// nibrig.study: a triplet study's folder read back — every participant's answers as records and
// arrays (model/study/study_results.hpp) — and its report, the one call `nibrig experiment report`
// makes (model/study/study_report.hpp): the judgments merged, the space fitted, each participant's
// agreement, a validation study's statistics.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "model/study/study_report.hpp"
#include "model/study/study_results.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/python_log.hpp"
#include "ui/python/space_types.hpp"
#include "ui/python/study_types.hpp"
#include "ui/python/submodules.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace study = model::study;

namespace {

std::vector<std::string> names_of(const study::StudyDefinition& d) {
  std::vector<std::string> names;
  for (const auto& s : d.stimuli) names.push_back(s.name);
  return names;
}

const char* choice_name(model::space::Choice c) {
  return c == model::space::Choice::left ? "left" : c == model::space::Choice::right ? "right" : "none";
}

// One value of every answer, participants in the study's order (by ID), trials in theirs.
template <typename T, typename Value>
py::array_t<T> per_answer(const Answers& a, Value value) {
  std::vector<T> v;
  for (const auto& p : a.study.participants)
    for (const auto& r : p.responses) v.push_back(static_cast<T>(value(r)));
  py::array_t<T> out(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), out.mutable_data());
  return out;
}

py::dict agreement(const model::space::AgreementTest& t) {
  py::dict d;
  d["agreements"] = t.agreements, d["trials"] = t.trials, d["fraction"] = t.fraction;
  d["z"] = t.z, d["p_value"] = t.p_value;
  return d;
}

py::object validation_record(const study::StudyReport& r, const std::vector<std::string>& names) {
  if (!r.validation) return py::none();
  const auto& v = *r.validation;
  py::dict d;
  d["space"] = r.validation_space;
  py::list triplets;
  for (std::size_t i = 0; i < r.validation_triplets.size(); ++i) {
    const auto& t = r.validation_triplets[i];
    py::dict one;
    one["reference"] = names[t.reference], one["a"] = names[t.a], one["b"] = names[t.b];
    one["count_a"] = t.count_a, one["count_b"] = t.count_b,
    one["predicted_p_a"] = r.validation_predicted[i];
    triplets.append(one);
  }
  d["triplets"] = triplets;
  d["majority_agreement"] = agreement(v.majority);
  d["individual_agreement"] = agreement(v.individual);
  d["mean_absolute_error"] = v.mean_absolute_error;
  d["pearson"] = v.probability_correlation
                     ? py::object(py::dict(py::arg("r") = v.probability_correlation->r,
                                           py::arg("p_value") = v.probability_correlation->p_value))
                     : py::none();
  d["pearson_missing_because"] = v.no_correlation_because;
  return d;
}

StudyReport shown_report(const study::StudyReport& r, const std::filesystem::path& folder) {
  StudyReport out;
  out.folder = folder;
  out.mode = study::mode_name(r.study.definition.mode);
  out.plan = study::plan_name(r.study.definition.plan);
  out.selection = r.selection == study::JudgmentSelection::paper ? "paper" : "every answer";
  out.stimuli = names_of(r.study.definition);
  out.triplets = r.judgments.triplets.size();
  out.responses = model::io::response_count(r.judgments);
  out.space = r.fitted ? py::cast(Space{r.fitted->file, r.fitted->warnings}) : py::none();
  out.with_descriptors = r.with_descriptors;
  out.mean_region_sd = r.fitted ? py::cast(r.fitted->mean_region_sd) : py::none();
  py::list participants;
  for (const auto& p : r.participants) {
    py::dict d;
    d["id"] = p.id, d["respondent"] = p.respondent, d["answers"] = p.answers,
    d["practice"] = p.practice;
    d["median_response_s"] = p.median_response_s;
    d["agreement_with_space"] = agreement(p.with_space);
    d["agreement_with_others"] = p.with_others ? py::object(agreement(*p.with_others)) : py::none();
    participants.append(d);
  }
  out.participants = participants;
  out.validation = validation_record(r, out.stimuli);
  out.warnings = r.warnings;
  return out;
}

StudyReport report_study(const std::filesystem::path& folder, const std::optional<std::filesystem::path>& output,
                         bool all_judgments, const std::optional<std::filesystem::path>& space,
                         const std::optional<std::filesystem::path>& catalog, int bootstrap, int starts, unsigned seed,
                         unsigned threads, const py::object& progress) {
  if (bootstrap < 0) throw std::invalid_argument("bootstrap is " + std::to_string(bootstrap) + "; expected 0 (no regions) or more");
  if (starts < 1) throw std::invalid_argument("starts is " + std::to_string(starts) + "; expected at least 1");
  const std::filesystem::path written = output.value_or(folder / "report");
  study::StudyReport reported;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        study::StudyReportSettings settings;
        if (all_judgments) settings.selection = study::JudgmentSelection::every_answer;
        settings.starts = starts;
        settings.bootstrap = bootstrap;
        settings.seed = seed;
        settings.threads = threads;
        settings.catalog = catalog.value_or(std::filesystem::path());
        settings.validation_space = space.value_or(std::filesystem::path());
        settings.progress = report;
        settings.stop = stop;
        reported = study::report_study(folder, written, settings);
      },
      progress);
  if (!reported.warnings.empty()) {
    const auto warn = py::module_::import("warnings").attr("warn");
    for (const auto& w : reported.warnings) warn(w);
  }
  return shown_report(reported, written);
}

}  // namespace

void add_study_module(py::module_ m) {
  py::class_<Answers>(m, "Answers", "A study's answers: every participant's log, practice included")
      .def_property_readonly("folder", [](const Answers& a) { return a.study.folder; })
      .def_property_readonly(
          "stimuli", [](const Answers& a) { return names_of(a.study.definition); },
          "The study's stimuli by name; reference, left and right index them")
      .def_property_readonly(
          "mode", [](const Answers& a) { return study::mode_name(a.study.definition.mode); },
          "'actuator', 'rig' or 'validation'")
      .def_property_readonly(
          "plan", [](const Answers& a) { return study::plan_name(a.study.definition.plan); },
          "'two-stage', 'adaptive' or 'file'")
      .def_property_readonly(
          "dims", [](const Answers& a) { return a.study.definition.dims; }, "Of the report's fit")
      .def_property_readonly(
          "warnings", [](const Answers& a) { return a.study.warnings; },
          "Cut-off lines dropped, participants left out, and why")
      .def_property_readonly(
          "participants",
          [](const Answers& a) {
            py::list out;
            for (const auto& p : a.study.participants) {
              py::dict d;
              d["id"] = p.record.id, d["seed"] = p.record.seed,
              d["respondent"] = p.record.respondent;
              d["created_utc"] = p.record.created_utc, d["answers"] = p.responses.size();
              d["main_answers"] = study::has_main_answers(p);
              out.append(d);
            }
            return out;
          },
          "Each participant (by ID): id, seed of their order, respondent (a person or the "
          "simulated observer), "
          "created_utc, answers (practice included), main_answers (whether any main trial is "
          "answered)")
      .def_property_readonly(
          "records",
          [](const Answers& a) {
            const auto names = names_of(a.study.definition);
            py::list out;
            for (const auto& p : a.study.participants)
              for (const auto& r : p.responses) {
                py::dict d;
                d["participant"] = p.record.id, d["trial"] = r.trial, d["practice"] = r.practice,
                d["stage"] = r.planned.stage;
                d["reference"] = names[r.planned.reference], d["left"] = names[r.planned.left],
                d["right"] = names[r.planned.right];
                d["chosen"] = choice_name(r.chosen);
                d["chosen_stimulus"] = r.chosen == model::space::Choice::left
                                           ? names[r.planned.left]
                                           : names[r.planned.right];
                d["response_s"] = r.response_s, d["plays"] = r.plays,
                d["answered_utc"] = r.answered_utc;
                out.append(d);
              }
            return out;
          },
          "Every answer as a dict: participant, trial (1-based, practice included), practice, "
          "stage, reference, left, "
          "right (stimulus names), chosen ('left' or 'right'), chosen_stimulus, response_s (s from "
          "the trial's start), "
          "plays (what was asked to play, R/A/B), answered_utc")
      .def_property_readonly(
          "participant",
          [](const Answers& a) {
            std::vector<std::string> v;
            for (const auto& p : a.study.participants)
              v.insert(v.end(), p.responses.size(), p.record.id);
            return v;
          },
          "Each answer's participant (the arrays' order)")
      .def_property_readonly(
          "trial",
          [](const Answers& a) {
            return per_answer<std::int64_t>(a, [](const auto& r) { return r.trial; });
          },
          "Each answer's trial number, 1-based, practice included")
      .def_property_readonly("practice",
                             [](const Answers& a) {
                               return per_answer<bool>(a, [](const auto& r) { return r.practice; });
                             })
      .def_property_readonly("stage",
                             [](const Answers& a) {
                               return per_answer<std::int64_t>(
                                   a, [](const auto& r) { return r.planned.stage; });
                             })
      .def_property_readonly(
          "reference",
          [](const Answers& a) {
            return per_answer<std::int64_t>(a, [](const auto& r) { return r.planned.reference; });
          },
          "Index into stimuli")
      .def_property_readonly("left",
                             [](const Answers& a) {
                               return per_answer<std::int64_t>(
                                   a, [](const auto& r) { return r.planned.left; });
                             })
      .def_property_readonly("right",
                             [](const Answers& a) {
                               return per_answer<std::int64_t>(
                                   a, [](const auto& r) { return r.planned.right; });
                             })
      .def_property_readonly(
          "chose_left",
          [](const Answers& a) {
            return per_answer<bool>(
                a, [](const auto& r) { return r.chosen == model::space::Choice::left; });
          },
          "True where the left candidate was judged closer to the reference")
      .def_property_readonly(
          "response_s",
          [](const Answers& a) {
            return per_answer<double>(a, [](const auto& r) { return r.response_s; });
          },
          "From each trial's start to its answer, s")
      .def(py::pickle(&answers_state, &answers_of))
      .def("__len__", [](const Answers& a) {
        std::size_t n = 0;
        for (const auto& p : a.study.participants) n += p.responses.size();
        return n;
      });

  m.def(
      "answers",
      [](const std::filesystem::path& folder) {
        ReleasedGil unlocked;
        return Answers{study::read_study(folder)};
      },
      py::arg("folder"),
      "Reads a study folder (`nibrig experiment run -o`): its stimuli and every participant's "
      "answers, practice "
      "included; arrays and records are copies (each answer is a record in the library)");

  py::class_<StudyReport>(m, "Report",
                          "A study's report, as `nibrig experiment report` gives and writes it")
      .def_readonly("folder", &StudyReport::folder,
                    "Where judgments.csv, space.json and report.json were written")
      .def_readonly("mode", &StudyReport::mode)
      .def_readonly("plan", &StudyReport::plan)
      .def_readonly("stimuli", &StudyReport::stimuli)
      .def_readonly(
          "selection", &StudyReport::selection,
          "'paper' (stage 2 and the stage-1 triplets that were not ties) or 'every answer'")
      .def_readonly("triplets", &StudyReport::triplets,
                    "Triplets judged (each participant's counted apart)")
      .def_readonly("responses", &StudyReport::responses)
      .def_property_readonly(
          "judgments_file", [](const StudyReport& r) { return r.folder / study::kReportJudgments; },
          "The merged judgments, the CSV nibrig.space.fit and read_judgments take")
      .def_property_readonly(
          "space",
          [](const StudyReport& r) { return py::module_::import("copy").attr("copy")(r.space); },
          "The fitted space (a nibrig.space.Space; a copy), tied to the catalog's descriptors when "
          "every stimulus is a catalog pairing; None for a validation study")
      .def_readonly("with_descriptors", &StudyReport::with_descriptors)
      .def_readonly("mean_region_sd", &StudyReport::mean_region_sd,
                    "Mean per-axis sd of a stimulus over the bootstrap refits, in the space's "
                    "units (0 without them)")
      .def_property_readonly(
          "participants",
          [](const StudyReport& r) {
            return py::module_::import("copy").attr("deepcopy")(r.participants);
          },
          "Each participant with main answers: id, respondent, answers, practice, "
          "median_response_s "
          "(s), agreement_with_space and agreement_with_others (None: nobody else judged their "
          "triplets), each a dict of agreements, trials, fraction, z and one-sided p_value against "
          "chance")
      .def_property_readonly(
          "validation",
          [](const StudyReport& r) {
            return py::module_::import("copy").attr("deepcopy")(r.validation);
          },
          "A validation study's statistics (Sec. 6.1) against the given space, as report.json's "
          "'validation'; None otherwise")
      .def_readonly("warnings", &StudyReport::warnings)
      .def(py::pickle(&study_report_state, &study_report_of));

  m.def("report", &report_study, py::arg("folder"), py::kw_only(), py::arg("output") = py::none(),
        py::arg("all_judgments") = false, py::arg("space") = py::none(), py::arg("catalog") = py::none(),
        py::arg("bootstrap") = 200, py::arg("starts") = 16, py::arg("seed") = 1u, py::arg("threads") = 0u,
        py::arg("progress") = py::none(),
        "Reports a study as `nibrig experiment report` does, writing judgments.csv, space.json and report.json into "
        "`output` (default: <folder>/report): the participants' judgments merged (the paper's selection, or every "
        "answer with all_judgments), the space fitted with the study's dims (`starts` random starts, `bootstrap` "
        "resamples for its regions, 0: none), each participant's agreement; a validation study is scored against "
        "`space` instead. Releases the GIL; Ctrl-C stops it.");
}

}  // namespace nibrig::ui::python
