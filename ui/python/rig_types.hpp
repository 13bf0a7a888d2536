// The Python classes nibrig.rig.RigSession and Comparison as C++ types: what a capture and a
// comparison give, and what nibrig.rig.session reads.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "model/io/comparison_file.hpp"
#include "model/io/rig_session.hpp"
#include "rig/comparison_run.hpp"

namespace nibrig::ui::python {

struct Session {
  model::io::RigSession session;
};

// What Python shows of a comparison run, kept as numbers so that it pickles (the capture's and the
// analysis' own records stay in the call that made them).
struct Comparison {
  model::io::ComparisonFile report;  // what `nibrig rig compare` writes as comparison.json
  std::string simulated;             // the simulated tool's name, as the engine gives it
  std::string simulated_modes;
  std::vector<double> frequencies_hz;
  std::vector<std::vector<double>> measured_mean, simulated_mean;  // per speed bin, m/s² peak
  rig::WaterfallRows rows;
  Session session;
};

// What a finished run leaves for Python.
Comparison comparison_of(rig::ComparisonRun run, model::io::ComparisonFile report,
                         std::string simulated_modes);

// Each as its records and samples and back (rig_pickle.cpp); a state that is not one is a
// ValueError naming the class.
pybind11::tuple session_state(const Session& session);
Session session_of(const pybind11::tuple& state);
pybind11::tuple comparison_state(const Comparison& comparison);
Comparison comparison_from(const pybind11::tuple& state);

// RigSession, Comparison and session(), added to the submodule before the calls that give them.
void add_rig_results(pybind11::module_ m);

}  // namespace nibrig::ui::python
