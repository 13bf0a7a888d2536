// How a study's Answers and Report pickle: as their values, bit for bit.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "ui/python/pickle_state.hpp"
#include "ui/python/study_types.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace study = model::study;

namespace {

constexpr const char* kAnswers = "Answers";
constexpr const char* kStudyReport = "Report";

template <typename Enum>
Enum answers_enum_of(const py::handle& value, Enum last) {
  const int v = value.cast<int>();
  if (v < 0 || v > static_cast<int>(last))
    throw std::invalid_argument(std::string(kAnswers) + ": not a pickled " + kAnswers);
  return static_cast<Enum>(v);
}

}  // namespace

// A study's answers as their values, bit for bit: its definition, each participant's record and
// every logged answer.
py::tuple answers_state(const Answers& a) {
  const auto& d = a.study.definition;
  py::list stimuli, listed, participants;
  for (const auto& s : d.stimuli) stimuli.append(py::make_tuple(s.name, s.tool, s.surface));
  for (const auto& t : d.listed_trials)
    listed.append(py::make_tuple(t.reference, t.left, t.right, t.stage));
  for (const auto& p : a.study.participants) {
    py::list responses;
    for (const auto& r : p.responses)
      responses.append(py::make_tuple(r.trial, r.practice, r.planned.reference, r.planned.left,
                                      r.planned.right, r.planned.stage, static_cast<int>(r.chosen),
                                      r.response_s, r.plays, r.answered_utc));
    participants.append(py::make_tuple(p.record.id, p.record.seed, p.record.respondent,
                                       p.record.created_utc, responses));
  }
  return py::make_tuple(a.study.folder,
                        py::make_tuple(stimuli, static_cast<int>(d.mode), static_cast<int>(d.plan),
                                       listed, d.trials, d.practice, d.break_every, d.dims),
                        participants, a.study.warnings);
}

Answers answers_of(const py::tuple& state) {
  require_state(state, 4, kAnswers);
  Answers a;
  a.study.folder = state[0].cast<std::filesystem::path>();
  const auto d = state[1].cast<py::tuple>();
  require_state(d, 8, kAnswers);
  auto& definition = a.study.definition;
  for (const auto& s : d[0].cast<py::list>()) {
    const auto t = s.cast<py::tuple>();
    require_state(t, 3, kAnswers);
    definition.stimuli.push_back(
        {t[0].cast<std::string>(), t[1].cast<std::string>(), t[2].cast<std::string>()});
  }
  definition.mode = answers_enum_of(d[1], study::StudyMode::validation);
  definition.plan = answers_enum_of(d[2], study::PlanKind::file);
  for (const auto& l : d[3].cast<py::list>()) {
    const auto t = l.cast<py::tuple>();
    require_state(t, 4, kAnswers);
    definition.listed_trials.push_back({t[0].cast<std::size_t>(), t[1].cast<std::size_t>(),
                                        t[2].cast<std::size_t>(), t[3].cast<int>()});
  }
  definition.trials = d[4].cast<std::size_t>();
  definition.practice = d[5].cast<std::size_t>();
  definition.break_every = d[6].cast<std::size_t>();
  definition.dims = d[7].cast<std::size_t>();
  for (const auto& p : state[2].cast<py::list>()) {
    const auto t = p.cast<py::tuple>();
    require_state(t, 5, kAnswers);
    study::ParticipantData participant;
    participant.record = {t[0].cast<std::string>(), t[1].cast<std::uint64_t>(),
                          t[2].cast<std::string>(), t[3].cast<std::string>()};
    for (const auto& r : t[4].cast<py::list>()) {
      const auto v = r.cast<py::tuple>();
      require_state(v, 10, kAnswers);
      study::LoggedResponse response;
      response.trial = v[0].cast<std::size_t>();
      response.practice = v[1].cast<bool>();
      response.planned = {v[2].cast<std::size_t>(), v[3].cast<std::size_t>(),
                          v[4].cast<std::size_t>(), v[5].cast<int>()};
      response.chosen = answers_enum_of(v[6], model::space::Choice::right);
      response.response_s = v[7].cast<double>();
      response.plays = v[8].cast<std::string>();
      response.answered_utc = v[9].cast<std::string>();
      // The arrays index the stimuli with these: an index beyond them is no pickled study.
      const auto n = definition.stimuli.size();
      if (response.planned.reference >= n || response.planned.left >= n ||
          response.planned.right >= n)
        throw std::invalid_argument(std::string(kAnswers) + ": not a pickled " + kAnswers);
      participant.responses.push_back(std::move(response));
    }
    a.study.participants.push_back(std::move(participant));
  }
  a.study.warnings = state[3].cast<std::vector<std::string>>();
  return a;
}

py::tuple study_report_state(const StudyReport& r) {
  return py::make_tuple(r.folder, r.mode, r.plan, r.selection, r.stimuli, r.triplets, r.responses,
                        r.space, r.with_descriptors, r.mean_region_sd, r.participants, r.validation,
                        r.warnings);
}

StudyReport study_report_of(const py::tuple& state) {
  require_state(state, 13, kStudyReport);
  StudyReport r;
  r.folder = state[0].cast<std::filesystem::path>();
  r.mode = state[1].cast<std::string>(), r.plan = state[2].cast<std::string>();
  r.selection = state[3].cast<std::string>();
  r.stimuli = state[4].cast<std::vector<std::string>>();
  r.triplets = state[5].cast<std::size_t>(), r.responses = state[6].cast<std::size_t>();
  r.space = state[7];
  r.with_descriptors = state[8].cast<bool>();
  r.mean_region_sd = state[9], r.participants = state[10], r.validation = state[11];
  r.warnings = state[12].cast<std::vector<std::string>>();
  return r;
}

}  // namespace nibrig::ui::python
