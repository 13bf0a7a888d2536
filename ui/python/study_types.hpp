// The Python classes nibrig.study.Answers and Report as C++ types, which the module
// (study_module.cpp) and their pickling (study_pickle.cpp) share.
#pragma once

#include <pybind11/pybind11.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "model/study/study_results.hpp"

namespace nibrig::ui::python {

struct Answers {
  model::study::StudyData study;
};

// What Python shows of a report, made once when it is reported: the participants' and the
// validation's records are Python dicts already, so the whole report pickles as its values.
struct StudyReport {
  std::filesystem::path folder;  // where it was written
  std::string mode, plan, selection;
  std::vector<std::string> stimuli;
  std::size_t triplets = 0, responses = 0;
  pybind11::object space;  // a nibrig.space.Space, or None
  bool with_descriptors = false;
  pybind11::object mean_region_sd, participants, validation;
  std::vector<std::string> warnings;
};

// Each as its values and back; a state that is not one is a ValueError naming the class.
pybind11::tuple answers_state(const Answers& answers);
Answers answers_of(const pybind11::tuple& state);
pybind11::tuple study_report_state(const StudyReport& report);
StudyReport study_report_of(const pybind11::tuple& state);

}  // namespace nibrig::ui::python
