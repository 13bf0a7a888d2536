// The Python classes nibrig.rig.RigSession and Comparison as C++ types: what a capture and a
// comparison give, and what nibrig.rig.session reads.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "model/io/comparison_file.hpp"
#include "model/io/rig_session.hpp"
#include "rig/comparison_run.hpp"

namespace nibrig::ui::python {

struct Session {
  model::io::RigSession session;
};

struct Comparison {
  rig::ComparisonRun run;
  model::io::ComparisonFile report;  // what `nibrig rig compare` writes as comparison.json
  std::string simulated_modes;
  Session session;
};

// RigSession, Comparison and session(), added to the submodule before the calls that give them.
void add_rig_results(pybind11::module_ m);

}  // namespace nibrig::ui::python
