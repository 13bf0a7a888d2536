// nibrig.design.loop: the design loop from a print back to its target (`nibrig design loop`) as
// one call: it opens or resumes the loop in its folder and runs it as far as it goes here
// (rig::drive_design_loop), returning every round's prediction and measurement.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <optional>
#include <stop_token>

#include "model/design/loop_session.hpp"
#include "rig/loop_print_capture.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/pickle_state.hpp"

namespace py = pybind11;

namespace nibrig::ui::python {

namespace {

namespace design = model::design;

struct LoopResult {
  std::filesystem::path folder;
  double threshold = 0.0;
  std::vector<design::LoopRoundRecord> rounds;
  std::optional<std::string> stopped;
  std::optional<int> awaiting;
};

py::array_t<double> vector_array(const Eigen::VectorXd& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

py::dict round_dict(const design::LoopRoundRecord& r) {
  py::dict d;
  d["round"] = r.number;
  d["design"] = design::to_string(r.design);
  d["predicted_distance"] = r.predicted_distance;
  d["predicted_distance_sd"] = r.predicted_distance_sd;
  d["chance_within_threshold"] = r.chance_within;
  d["predicted_position"] = vector_array(r.predicted_position);
  d["measured_distance"] = r.measured ? py::cast(r.measured->distance) : py::none();
  d["measured_distance_sd"] = r.measured ? py::cast(r.measured->distance_sd) : py::none();
  d["measured_position"] = r.measured ? py::object(vector_array(r.measured->position)) : py::none();
  d["stopped"] = r.stopped.empty() ? py::none() : py::cast(r.stopped);
  return d;
}

LoopResult run_loop(const std::filesystem::path& folder, const std::optional<std::string>& target,
                    const std::optional<std::string>& surface,
                    const std::optional<std::filesystem::path>& space, bool resume,
                    const std::string& rule, const std::optional<int>& rounds,
                    const std::pair<std::string, std::string>& mix,
                    const std::optional<std::filesystem::path>& catalog,
                    const std::optional<std::string>& forcing,
                    const std::optional<std::string>& printer, bool simulated,
                    const std::optional<std::filesystem::path>& simulated_forcing, unsigned seed,
                    const std::optional<double>& seconds,
                    const std::optional<std::filesystem::path>& replay_prints,
                    const py::object& progress) {
  if (simulated && replay_prints)
    throw std::invalid_argument("simulated, replay_prints: measure the prints one way, not both");
  std::optional<design::LoopRequest> request;
  std::optional<rig::LoopCaptureOptions> capture;
  if (resume) {
    if (target || surface || space)
      throw std::invalid_argument(
          "resume: the loop keeps what its loop.json says; give no target, surface or space "
          "(rounds alone may change)");
  } else {
    design::LoopRequest r;
    r.target = target.value_or("");
    r.surface = surface.value_or("");
    r.space_file = space.value_or(std::filesystem::path());
    r.catalog_file = catalog.value_or(std::filesystem::path());
    r.forcing = forcing.value_or("");
    r.printer = printer.value_or("");
    r.first_material = design::catalog_material_name(mix.first);
    r.second_material = design::catalog_material_name(mix.second);
    r.rule = design::parse_next_print_rule(rule);
    r.max_rounds = rounds.value_or(design::kDefaultLoopRounds);
    design::check_loop_request(r);  // before the long call: what a new loop lacks, named
    if (replay_prints) {
      // Replayed prints are the only ones the loop can measure: it proposes nothing else.
      capture = rig::replay_recorded_prints(*replay_prints, r, 0.0);
      r.candidates = rig::designs_of(capture->recorded_prints);
    }
    request = r;
  }
  LoopResult out;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        auto session = resume && rounds
                           ? design::LoopSession::resume_with_rounds(folder, *rounds, report)
                           : design::LoopSession::open(folder, request, report);
        if (replay_prints && !capture)
          capture = rig::replay_recorded_prints(*replay_prints, session->request(), 0.0);
        if (capture) {
          capture->seconds = seconds;
          capture->cancel = stop;
        }
        if (simulated) {
          capture.emplace();
          capture->rig.kind = rig::RigKind::simulated;
          capture->rig.seed = seed;
          capture->rig.speedup = 0.0;
          capture->sounds.catalog = catalog.value_or(std::filesystem::path());
          capture->sounds.forcing_model = simulated_forcing.value_or(std::filesystem::path());
          capture->seconds = seconds;
          capture->cancel = stop;
        }
        rig::drive_design_loop(
            *session, capture,
            [&](rig::LoopStep, int round) { report("rounds", static_cast<std::size_t>(round), 0); },
            stop);
        out.folder = session->folder();
        out.threshold = session->threshold();
        out.rounds = session->rounds();
        if (session->stopped() != design::LoopStop::none)
          out.stopped = design::describe(session->stopped());
        out.awaiting = session->awaiting_measurement();
      },
      progress);
  return out;
}

// A loop pickles as its rounds' numbers (its folder stays where it is, named).
py::tuple loop_state(const LoopResult& l) {
  std::vector<py::tuple> rounds;
  for (const auto& r : l.rounds) {
    py::object measured = py::none();
    if (r.measured)
      measured = py::make_tuple(r.measured->distance, r.measured->distance_sd, r.measured->position,
                                r.measured->descriptors);
    rounds.push_back(py::make_tuple(r.number, design_point_state(r.design), r.predicted_distance,
                                    r.predicted_distance_sd, r.chance_within, r.predicted_position,
                                    measured, r.stopped));
  }
  return py::make_tuple(l.folder, l.threshold, rounds, l.stopped, l.awaiting);
}

LoopResult loop_of(const py::tuple& state) {
  require_state(state, 5, "DesignLoop");
  LoopResult l;
  l.folder = state[0].cast<std::filesystem::path>();
  l.threshold = state[1].cast<double>();
  for (const auto& item : state[2].cast<py::list>()) {
    const auto t = item.cast<py::tuple>();
    require_state(t, 8, "DesignLoop");
    design::LoopRoundRecord r;
    r.number = t[0].cast<int>();
    r.design = design_point_of(t[1], "DesignLoop");
    r.predicted_distance = t[2].cast<double>();
    r.predicted_distance_sd = t[3].cast<double>();
    r.chance_within = t[4].cast<double>();
    r.predicted_position = t[5].cast<Eigen::VectorXd>();
    if (!t[6].is_none()) {
      const auto m = t[6].cast<py::tuple>();
      require_state(m, 4, "DesignLoop");
      r.measured =
          design::LoopMeasuredRecord{m[0].cast<double>(), m[1].cast<double>(),
                                     m[2].cast<Eigen::VectorXd>(), m[3].cast<Eigen::VectorXd>()};
    }
    r.stopped = t[7].cast<std::string>();
    l.rounds.push_back(std::move(r));
  }
  l.stopped = state[3].cast<std::optional<std::string>>();
  l.awaiting = state[4].cast<std::optional<int>>();
  return l;
}

}  // namespace

void add_design_loop(py::module_ m) {
  py::class_<LoopResult>(m, "DesignLoop", "A design loop's rounds as far as it has gone")
      .def_property_readonly("folder", [](const LoopResult& l) { return l.folder; })
      .def_property_readonly(
          "threshold", [](const LoopResult& l) { return l.threshold; },
          "The space's just-noticeable distance: a print within it is as close as the space tells")
      .def_property_readonly(
          "rounds",
          [](const LoopResult& l) {
            py::list out;
            for (const auto& r : l.rounds) out.append(round_dict(r));
            return out;
          },
          "Per round: design, predicted and measured distance (with sd) and position, chance "
          "within the threshold")
      .def_property_readonly(
          "measured_distances",
          [](const LoopResult& l) {
            std::vector<double> d;
            for (const auto& r : l.rounds)
              if (r.measured) d.push_back(r.measured->distance);
            return py::array_t<double>(static_cast<py::ssize_t>(d.size()), d.data());
          },
          "The measured distance to the target per measured round")
      .def_property_readonly(
          "stopped", [](const LoopResult& l) { return l.stopped; },
          "Why the loop stopped, or None while it goes on")
      .def_property_readonly(
          "awaiting", [](const LoopResult& l) { return l.awaiting; },
          "The round whose print awaits its measurement (capture it into "
          "folder/round-N/session, then loop(folder, resume=True)), or None")
      .def(py::pickle(&loop_state, &loop_of));

  m.def(
      "loop", &run_loop, py::arg("folder"), py::kw_only(), py::arg("target") = py::none(),
      py::arg("surface") = py::none(), py::arg("space") = py::none(), py::arg("resume") = false,
      py::arg("rule") = design::rule_name(design::kDefaultNextPrintRule),
      py::arg("rounds") = py::none(),
      py::arg("mix") = std::pair<std::string, std::string>{"vero", "DM85"},
      py::arg("catalog") = py::none(), py::arg("forcing") = py::none(),
      py::arg("printer") = py::none(), py::arg("simulated") = false,
      py::arg("simulated_forcing") = py::none(), py::arg("seed") = 1,
      py::arg("seconds") = py::none(), py::arg("replay_prints") = py::none(),
      py::arg("progress") = py::none(),
      "The design loop of `nibrig design loop` in `folder`: a new one for target (tool/surface) "
      "on surface in "
      "space, or resume=True (rounds then sets a new limit: a loop stopped at its old one goes on; "
      "a new loop takes the command line's default). Runs as far as it goes here: with "
      "simulated=True each print is "
      "measured on the "
      "simulated rig (its prints playing simulated_forcing, default the loop's model); without, "
      "it stops at a "
      "round awaiting its print's measurement. replay_prints (a folder of the paper's "
      "recordings) stands the prints recorded there in for printing: the loop proposes only "
      "those and replays each one's vibration and friction recordings. Releases the GIL; "
      "Ctrl-C stops it between steps.");
}

}  // namespace nibrig::ui::python
