// nibrig.space's scores: Space.evaluate (a space's predictions of judged triplets against their
// answers, as `nibrig space evaluate`) and validate (the cross-validated error of spaces of several
// dimensions, weights and models, as `nibrig space validate`): model/space/space_evaluation.hpp.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "model/numeric/cancellation.hpp"
#include "model/space/judgment_model.hpp"
#include "model/space/space_evaluation.hpp"
#include "model/space/space_fit_request.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/pickle_state.hpp"
#include "ui/python/python_log.hpp"
#include "ui/python/space_types.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace space = model::space;

namespace {

space::SpaceEvaluation evaluate(const Space& s, const py::object& judgments, const std::optional<std::filesystem::path>& catalog) {
  std::filesystem::path label;
  const model::io::TripletSet judged = judgments_argument(judgments, "judgments", label);
  ReleasedGil unlocked;
  return space::evaluate_space(s.file, "the space", judged, label,
                               catalog.value_or(std::filesystem::path()));
}

space::Validation validate(const py::object& judgments, const std::vector<std::size_t>& dims,
                           const std::vector<double>& lambdas,
                           const std::vector<std::string>& models, int folds, int starts,
                           unsigned seed, const std::optional<std::filesystem::path>& descriptors,
                           unsigned threads, const py::object& progress) {
  space::DimensionScanOptions scan;
  scan.dims = dims;
  scan.lambdas = lambdas;
  scan.models.clear();
  for (const auto& name : models) {
    if (name == "all") {
      scan.models = space::every_family();
      break;
    }
    try {
      scan.models.push_back(space::parse_family(name));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("models: ") + e.what());
    }
  }
  scan.cross_validation.folds = folds;
  scan.cross_validation.seed = seed;
  scan.cross_validation.fit.starts = starts;
  scan.cross_validation.fit.seed = seed;
  scan.cross_validation.fit.threads = threads;
  const std::filesystem::path catalog = descriptors.value_or(std::filesystem::path());
  // The library's bounds, in these arguments' names, before the judgments are read.
  space::check_dimension_scan(scan, catalog, [](space::SpaceFitField field) -> std::string {
    return field == space::SpaceFitField::lambda ? "lambdas" : space::field_name(field);
  });
  std::filesystem::path label;
  model::io::TripletSet judged = judgments_argument(judgments, "judgments", label);
  space::Validation out;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        scan.cross_validation.fit.stop = stop;
        out = space::validate_space(
            std::move(judged), catalog, scan,
            [&](std::size_t done, std::size_t total) { report("fitting folds", done, total); });
      },
      progress);
  return out;
}

py::object correlation(const std::optional<space::Correlation>& c) {
  if (!c) return py::none();
  py::dict d;
  d["r"] = c->r, d["p_value"] = c->p_value, d["n"] = c->n;
  return d;
}

py::tuple agreement_state(const space::AgreementTest& a) {
  return py::make_tuple(a.agreements, a.trials, a.fraction, a.z, a.p_value);
}

space::AgreementTest agreement_of(const py::handle& state) {
  const auto t = state.cast<std::tuple<double, double, double, double, double>>();
  return {std::get<0>(t), std::get<1>(t), std::get<2>(t), std::get<3>(t), std::get<4>(t)};
}

py::object correlation_state(const std::optional<space::Correlation>& c) {
  return c ? py::object(py::make_tuple(c->r, c->p_value, c->n)) : py::none();
}

std::optional<space::Correlation> correlation_of(const py::handle& state) {
  if (state.is_none()) return std::nullopt;
  const auto t = state.cast<std::tuple<double, double, std::size_t>>();
  return space::Correlation{std::get<0>(t), std::get<1>(t), std::get<2>(t)};
}

// A result held between calls (returned from a joblib worker, say) pickles as its numbers.
py::tuple evaluation_state(const space::SpaceEvaluation& e) {
  const auto& s = e.scores;
  return py::make_tuple(s.triplets, s.responses, agreement_state(s.majority),
                        agreement_state(s.individual), s.mean_absolute_error, s.log_loss,
                        correlation_state(s.probability_correlation), s.no_correlation_because,
                        e.placed_from_descriptors);
}

space::SpaceEvaluation evaluation_of(const py::tuple& state) {
  require_state(state, 9, "Evaluation");
  space::SpaceEvaluation e;
  e.scores.triplets = state[0].cast<std::size_t>();
  e.scores.responses = state[1].cast<std::size_t>();
  e.scores.majority = agreement_of(state[2]);
  e.scores.individual = agreement_of(state[3]);
  e.scores.mean_absolute_error = state[4].cast<double>();
  e.scores.log_loss = state[5].cast<double>();
  e.scores.probability_correlation = correlation_of(state[6]);
  e.scores.no_correlation_because = state[7].cast<std::string>();
  e.placed_from_descriptors = state[8].cast<std::size_t>();
  return e;
}

py::tuple validation_state(const space::Validation& v) {
  py::list points;
  for (const auto& p : v.points)
    points.append(py::make_tuple(p.dims, p.lambda, space::family_name(p.model), p.mean_error,
                                 p.sd_error, p.majority_agreement, p.individual_agreement,
                                 p.log_loss));
  return py::make_tuple(v.triplets, v.responses, points,
                        correlation_state(v.rank_correlation_with_names));
}

space::Validation validation_of(const py::tuple& state) {
  require_state(state, 4, "Validation");
  space::Validation v;
  v.triplets = state[0].cast<std::size_t>();
  v.responses = state[1].cast<std::size_t>();
  for (const auto& item : state[2].cast<py::list>()) {
    const auto t = item.cast<
        std::tuple<std::size_t, double, std::string, double, double, double, double, double>>();
    v.points.push_back({std::get<0>(t), std::get<1>(t), space::parse_family(std::get<2>(t)),
                        std::get<3>(t), std::get<4>(t), std::get<5>(t), std::get<6>(t),
                        std::get<7>(t)});
  }
  v.rank_correlation_with_names = correlation_of(state[3]);
  return v;
}

}  // namespace

void add_space_scores(py::module_ m) {
  py::class_<space::SpaceEvaluation>(
      m, "Evaluation", "A space's predictions of judged triplets scored against their answers")
      .def_property_readonly("triplets",
                             [](const space::SpaceEvaluation& e) { return e.scores.triplets; })
      .def_property_readonly("responses",
                             [](const space::SpaceEvaluation& e) { return e.scores.responses; })
      .def_readonly(
          "placed_from_descriptors", &space::SpaceEvaluation::placed_from_descriptors,
          "Judged stimuli the space was not fitted to, placed from the catalog's descriptors")
      .def_property_readonly(
          "majority_agreement",
          [](const space::SpaceEvaluation& e) { return e.scores.majority.fraction; },
          "Share of untied triplets whose majority answer is predicted (0.5 counts half)")
      .def_property_readonly(
          "majority_trials",
          [](const space::SpaceEvaluation& e) { return e.scores.majority.trials; })
      .def_property_readonly(
          "majority_z", [](const space::SpaceEvaluation& e) { return e.scores.majority.z; },
          "The agreement's z against chance (normal approximation of Binomial(n, 1/2))")
      .def_property_readonly(
          "majority_p_value",
          [](const space::SpaceEvaluation& e) { return e.scores.majority.p_value; },
          "One-sided: P(Z >= z)")
      .def_property_readonly(
          "individual_agreement",
          [](const space::SpaceEvaluation& e) { return e.scores.individual.fraction; },
          "Share of every individual answer predicted")
      .def_property_readonly(
          "mean_absolute_error",
          [](const space::SpaceEvaluation& e) { return e.scores.mean_absolute_error; },
          "Mean over triplets of |p_predicted - p_observed| (the paper's 'error')")
      .def_property_readonly(
          "log_loss", [](const space::SpaceEvaluation& e) { return e.scores.log_loss; },
          "Mean -log P(the answer given) per response, nats")
      .def_property_readonly(
          "pearson",
          [](const space::SpaceEvaluation& e) {
            return correlation(e.scores.probability_correlation);
          },
          "Predicted vs observed probability: {'r', 'p_value', 'n'}, or None (see "
          "no_correlation_because)")
      .def_property_readonly(
          "no_correlation_because",
          [](const space::SpaceEvaluation& e) { return e.scores.no_correlation_because; })
      .def(py::pickle(&evaluation_state, &evaluation_of));

  py::class_<space::Validation>(m, "Validation",
                                "Cross-validated spaces of several dimensions, weights and models")
      .def_readonly("triplets", &space::Validation::triplets)
      .def_readonly("responses", &space::Validation::responses)
      .def_property_readonly(
          "points",
          [](const space::Validation& v) {
            py::list out;
            for (const auto& p : v.points) {
              py::dict d;
              d["dims"] = p.dims, d["lambda"] = p.lambda, d["model"] = space::family_name(p.model);
              d["mean_error"] = p.mean_error, d["sd_error"] = p.sd_error;
              d["majority_agreement"] = p.majority_agreement, d["individual_agreement"] = p.individual_agreement;
              d["log_loss"] = p.log_loss;
              out.append(d);
            }
            return out;
          },
          "One dict per dims x lambda x model: mean_error and sd_error (of the held-out mean "
          "|p_predicted - "
          "p_observed| over folds), majority_agreement, individual_agreement, log_loss (nats per "
          "response)")
      .def_property_readonly(
          "rank_correlation_with_names",
          [](const space::Validation& v) { return correlation(v.rank_correlation_with_names); },
          "When every stimulus name ends in a number and dims holds 1: Spearman's rho of a 1-D "
          "fit's coordinate with those numbers, {'r', 'p_value', 'n'}; else None")
      .def(py::pickle(&validation_state, &validation_of));

  py::object space_class = m.attr("Space");
  space_class.attr("evaluate") =
      py::cpp_function(&evaluate, py::name("evaluate"), py::is_method(space_class),
                       py::sibling(py::getattr(space_class, "evaluate", py::none())),
                       py::arg("judgments"), py::arg("catalog") = py::none(),
                       "Scores the space's predictions of judged triplets (Judgments, or a file) "
                       "against their answers, as "
                       "`nibrig space evaluate`; stimuli it was not fitted to are placed from "
                       "`catalog`'s descriptors");

  m.def("validate", &validate, py::arg("judgments"),
        py::arg("dims") = std::vector<std::size_t>{1, 2, 3}, py::kw_only(),
        py::arg("lambdas") = std::vector<double>{0.0},
        py::arg("models") = std::vector<std::string>{"probit"}, py::arg("folds") = 5u,
        py::arg("starts") = 8, py::arg("seed") = 1u, py::arg("descriptors") = py::none(),
        py::arg("threads") = 0u, py::arg("progress") = py::none(),
        "k-fold cross-validation of a space per number of dimensions, weight λ (lambdas above 0 "
        "need descriptors, "
        "a catalog) and judgment model (of MODELS, or 'all' for every one), as `nibrig space "
        "validate`. seed: "
        "seeds the folds and the starts, so one seed gives one table; threads: worker threads, 0 "
        "for one per "
        "core; progress counts fold fits. Releases the GIL; Ctrl-C stops it.");
}

}  // namespace nibrig::ui::python
