// nibrig.space: fit a perceptual space from triplet judgments (the one call `nibrig space fit` and
// the panel make: model/space/space_fit_file.hpp), read and write it, predict judgments and place
// tools from their descriptors with their regions.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <unordered_map>

#include "model/design/default_space.hpp"
#include "model/io/triplets.hpp"
#include "model/space/bootstrap.hpp"
#include "model/space/judgment_model.hpp"
#include "model/space/space_file.hpp"
#include "model/space/space_fit_file.hpp"
#include "model/space/space_fit_request.hpp"
#include "model/space/space_inputs.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/numpy_views.hpp"
#include "ui/python/pickle_state.hpp"
#include "ui/python/python_log.hpp"
#include "ui/python/space_types.hpp"
#include "ui/python/submodules.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace space = model::space;

namespace {

// A judgment model's family by its name, the argument named when there is none such.
space::ModelFamily family_argument(const std::string& name, const char* argument) {
  try {
    return space::parse_family(name);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(argument) + ": " + e.what());
  }
}

Space fit(const py::object& judgments_given, std::size_t dims,
          const std::optional<std::filesystem::path>& descriptors, double lambda,
          const std::string& model, const std::vector<std::string>& models, int folds, int starts,
          unsigned seed, int bootstrap, unsigned threads, const py::object& progress) {
  space::SpaceFitRequest request;
  request.dims = dims;
  request.lambda = lambda;
  request.descriptors = descriptors.value_or(std::filesystem::path());
  auto& settings = request.settings;
  settings.starts = starts;
  settings.seed = seed;
  settings.threads = threads;
  settings.bootstrap = bootstrap;
  settings.folds = folds;
  settings.choose_model = model == "auto";
  if (!settings.choose_model) settings.model = family_argument(model, "model");
  request.candidates_listed = !models.empty();
  if (!models.empty()) {
    settings.candidates.clear();
    for (const auto& name : models) settings.candidates.push_back(family_argument(name, "models"));
  }
  space::check_space_fit(
      request);  // the library's bounds, in these arguments' names, before any work
  const std::filesystem::path& catalog = request.descriptors;
  std::filesystem::path label;
  model::io::TripletSet judged = judgments_argument(judgments_given, "judgments", label);
  Space out;
  {
    ReleasedGil unlocked;  // the descriptors' catalog takes a moment to read
    const auto in = space::space_inputs(std::move(judged), catalog, dims, lambda);
    py::gil_scoped_acquire locked;
    run_long_call(
        [&](std::stop_token stop, const Report& report) {
          settings.stop = stop;
          auto fitted = space::fit_space_file(in, label, catalog, settings, report);
          out.file = std::move(fitted.file);
          out.warnings = std::move(fitted.warnings);
        },
        progress);
  }
  if (!out.warnings.empty()) {
    const auto warn = py::module_::import("warnings").attr("warn");
    for (const auto& w : out.warnings) warn(w);
  }
  return out;
}

// A triplet's three stimuli, each a name or an index into the space's stimuli.
std::size_t stimulus_of(const Space& s, const py::handle& given, std::size_t row) {
  if (py::isinstance<py::str>(given)) return s.index_of(given.cast<std::string>());
  const long long i = given.cast<long long>();
  if (i < 0 || i >= static_cast<long long>(s.file.stimuli.size()))
    throw std::invalid_argument("triplets[" + std::to_string(row) + "]: " + std::to_string(i) +
                                " is not a stimulus index of this space (0 to " +
                                std::to_string(s.file.stimuli.size() - 1) + ")");
  return static_cast<std::size_t>(i);
}

py::array_t<double> predict_triplets(const Space& s, const py::object& triplets) {
  const py::sequence rows = py::isinstance<py::array>(triplets)
                                ? py::sequence(triplets.attr("tolist")())
                                : triplets.cast<py::sequence>();
  std::vector<std::array<std::size_t, 3>> which;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const py::sequence row = rows[k].cast<py::sequence>();
    if (row.size() != 3)
      throw std::invalid_argument("triplets[" + std::to_string(k) +
                                  "]: expected (reference, first, second), found " +
                                  std::to_string(row.size()) + " values");
    const std::array<std::size_t, 3> t{stimulus_of(s, row[0], k), stimulus_of(s, row[1], k),
                                       stimulus_of(s, row[2], k)};
    if (t[0] == t[1] || t[0] == t[2] || t[1] == t[2])
      throw std::invalid_argument(
          "triplets[" + std::to_string(k) +
          "]: expected three different stimuli (a reference is not a candidate)");
    which.push_back(t);
  }
  py::array_t<double> p(static_cast<py::ssize_t>(which.size()));
  auto out = p.mutable_unchecked<1>();
  for (std::size_t k = 0; k < which.size(); ++k)
    out(static_cast<py::ssize_t>(k)) = space::probability_first(
        s.file.model, s.file.coordinates, which[k][0], which[k][1], which[k][2]);
  return p;
}

// A square matrix from anything numpy reads as one (any order, a nested list), named on refusal.
Eigen::MatrixXd square_matrix(const py::object& given, const char* argument, Eigen::Index size) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
  if (!a || a.ndim() != 2 || a.shape(0) != size || a.shape(1) != size)
    throw std::invalid_argument(std::string(argument) + ": expected a " + std::to_string(size) +
                                " x " + std::to_string(size) +
                                " matrix of numbers (one row and column per descriptor)");
  Eigen::MatrixXd m(size, size);
  const auto v = a.unchecked<2>();
  for (Eigen::Index r = 0; r < size; ++r)
    for (Eigen::Index c = 0; c < size; ++c) m(r, c) = v(r, c);
  return m;
}

Placement place(const Space& s, const py::object& descriptors, const py::object& error) {
  if (!s.file.descriptor_map)
    throw std::invalid_argument("this space has no descriptor map (fit it with descriptors=a catalog)");
  const auto& names = s.file.descriptor_map->descriptor_names;
  Eigen::VectorXd x(static_cast<Eigen::Index>(names.size()));
  if (py::isinstance<py::dict>(descriptors)) {
    const auto d = descriptors.cast<py::dict>();
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (!d.contains(names[i])) throw std::invalid_argument("descriptors: no '" + names[i] + "', which the map needs");
      x(static_cast<Eigen::Index>(i)) = d[py::str(names[i])].cast<double>();
    }
  } else {
    const auto v = descriptors.cast<std::vector<double>>();
    if (v.size() != names.size())
      throw std::invalid_argument("descriptors: " + std::to_string(v.size()) + " values; the map takes " +
                                  std::to_string(names.size()) + " (" + names.front() + ", ...)");
    for (std::size_t i = 0; i < v.size(); ++i) x(static_cast<Eigen::Index>(i)) = v[i];
  }
  if (error.is_none()) return {space::place_from_descriptors(*s.file.descriptor_map, x)};
  return {space::place_from_descriptors(*s.file.descriptor_map, x,
                                        square_matrix(error, "error", x.size()))};
}

// Semi-axes and angle of the region in the plane of axes 1 and 2 at each level.
std::vector<std::tuple<double, double, double>> ellipses(const Placement& p, const std::vector<double>& levels) {
  const auto region = space::gaussian_region(p.placement.mean, p.placement.covariance, levels);
  std::vector<std::tuple<double, double, double>> out;
  const Eigen::Index y = p.placement.mean.size() > 1 ? 1 : 0;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const auto e = space::plane_ellipse(region, k, 0, y);
    out.emplace_back(e.semi_axis_1, e.semi_axis_2, e.angle_rad);
  }
  return out;
}

py::list model_scores(const Space& s) {
  py::list out;
  for (const auto& score : s.file.model_scores) {
    py::dict d;
    d["family"] = score.family, d["log_loss"] = score.log_loss;
    d["majority_agreement"] = score.majority_agreement,
    d["individual_agreement"] = score.individual_agreement;
    d["mean_error"] = score.mean_error;
    out.append(d);
  }
  return out;
}

constexpr const char* kPickledSpace = "a pickled nibrig.space.Space";

}  // namespace

void add_space_module(py::module_ m) {
  py::class_<Placement>(m, "Placement",
                        "A tool placed from its descriptors: a Gaussian position in the space")
      .def_property_readonly(
          "mean",
          [](const py::object& self) {
            return vector_view(self.cast<const Placement&>().placement.mean, self);
          },
          "Its position (one value per axis, in the space's units); a view, not a copy")
      .def_property_readonly(
          "covariance",
          [](const py::object& self) {
            return matrix_view(self.cast<const Placement&>().placement.covariance, self);
          },
          "The position's covariance (axes × axes, squared units): the map's scatter and its "
          "uncertainty")
      .def("ellipses", &ellipses, py::arg("levels") = std::vector<double>{0.68, 0.95},
           "The region in the plane of axes 1 and 2 at each level: (semi_axis_1, semi_axis_2, "
           "angle in radians "
           "from axis 1) per level")
      .def(py::pickle(
          [](const Placement& p) {
            return py::make_tuple(
                std::vector<double>(p.placement.mean.data(),
                                    p.placement.mean.data() + p.placement.mean.size()),
                std::vector<double>(p.placement.covariance.data(),
                                    p.placement.covariance.data() + p.placement.covariance.size()));
          },
          [](const py::tuple& state) {
            require_state(state, 2, "Placement");
            const auto mean = state[0].cast<std::vector<double>>();
            const auto covariance = state[1].cast<std::vector<double>>();
            const auto n = static_cast<Eigen::Index>(mean.size());
            if (covariance.size() != mean.size() * mean.size())
              throw std::invalid_argument("Placement: not a pickled Placement");
            Placement p;
            p.placement.mean = Eigen::Map<const Eigen::VectorXd>(mean.data(), n);
            p.placement.covariance = Eigen::Map<const Eigen::MatrixXd>(covariance.data(), n, n);
            return p;
          }));

  add_space_judgments(m);

  py::class_<Space>(m, "Space", "A perceptual space fitted from triplet judgments (Sec. 4)")
      .def_property_readonly(
          "stimuli", [](const Space& s) { return s.file.stimuli; }, "The judged stimuli, in order")
      .def_property_readonly(
          "dims",
          [](const Space& s) { return static_cast<std::size_t>(s.file.coordinates.rows()); },
          "Its number of axes")
      .def_property_readonly(
          "coordinates",
          [](const py::object& self) {
            return columns_as_rows_view(self.cast<const Space&>().file.coordinates, self);
          },
          "Each stimulus's position: an array of stimuli × dims (a row per stimulus, as "
          "scikit-learn lays out "
          "samples), in the space's units (one unit of difference in distance is 75 % preference "
          "under the "
          "paper's model); a read-only view, not a copy")
      .def_property_readonly(
          "model", [](const Space& s) { return space::family_name(s.file.model.family); },
          "The judgment model's family: 'probit' (the paper's), 'logistic', 'student-t', with "
          "'+lapse' and '+noise'")
      .def_property_readonly(
          "model_description", [](const Space& s) { return space::describe_model(s.file.model); },
          "The judgment model with its fitted parts, in words (scale, lapse, noise)")
      .def_property_readonly(
          "model_reason", [](const Space& s) { return s.file.model_reason; },
          "Why this model: given, or the cross-validation that chose it")
      .def_property_readonly(
          "scale", [](const Space& s) { return s.file.model.scale; },
          "The model's scale s: P = link(s · (d_b − d_a)) for distances in the space's units")
      .def_property_readonly(
          "lapse", [](const Space& s) { return s.file.model.lapse; },
          "The share of answers given at random (0 without a lapse)")
      .def_property_readonly(
          "lam", [](const Space& s) { return s.file.lambda; },
          "λ, the weight that tied the axes to the descriptors (0: none)")
      .def_property_readonly(
          "negative_log_likelihood", [](const Space& s) { return s.file.negative_log_likelihood; },
          "Of the judgments fitted, in nats")
      .def_property_readonly(
          "responses", [](const Space& s) { return s.file.responses; },
          "The answers fitted (the sum of the judgments' counts)")
      .def_property_readonly(
          "triplets", [](const Space& s) { return s.file.triplets; }, "The triplets fitted")
      .def_property_readonly(
          "judgments", [](const Space& s) { return s.file.judgments; },
          "What was fitted: the judgments' file, or 'judgments given as arrays'")
      .def_property_readonly(
          "model_scores", &model_scores,
          "With model='auto': one dict per candidate, as the cross-validation scored it "
          "(family, log_loss in nats per held-out answer, majority_agreement, "
          "individual_agreement, mean_error); empty when the model was given")
      .def_property_readonly(
          "descriptor_names", [](const Space& s) { return s.file.descriptor_names; },
          "The catalog descriptors the axes were tied to and the map reads, in order")
      .def_property_readonly(
          "has_descriptor_map", [](const Space& s) { return s.file.descriptor_map.has_value(); },
          "Whether tools can be placed from their descriptors (place)")
      .def_property_readonly(
          "warnings", [](const Space& s) { return s.warnings; },
          "What the fit warned of (also given to Python's warnings when it ran): e.g. too "
          "few stimuli for a descriptor map")
      .def("predict", &predict_triplets, py::arg("triplets"),
           "P(the first candidate is judged closer to the reference) for each (reference, first, "
           "second): "
           "stimulus names, or indices into stimuli (an (n, 3) integer array), under the space's "
           "judgment model")
      .def("place", &place, py::arg("descriptors"), py::arg("error") = py::none(),
           "Places a tool from its descriptors (a dict by name, or values in descriptor_names' "
           "order) through the "
           "space's descriptor map; `error`, the descriptors' own covariance (a predicted "
           "design's), widens the region")
      .def(
          "save",
          [](const Space& s, const std::filesystem::path& file) {
            ReleasedGil unlocked;
            space::write_space_file(file, s.file);
          },
          py::arg("path"), "Writes the space file (FORMATS.md 'Perceptual space'), atomically")
      .def(py::pickle(
          [](const Space& s) {
            return py::make_tuple(space::space_file_text(s.file, kPickledSpace), s.warnings);
          },
          [](const py::tuple& state) {
            require_state(state, 2, "Space");
            return Space{space::parse_space_file(state[0].cast<std::string>(), kPickledSpace),
                         state[1].cast<std::vector<std::string>>()};
          }))
      .def("__repr__", [](const Space& s) {
        return "<nibrig.space.Space: " + std::to_string(s.file.coordinates.rows()) + "-D, " +
               std::to_string(s.file.stimuli.size()) + " stimuli, " + space::family_name(s.file.model.family) + ">";
      });

  py::list families;
  for (const auto& f : space::every_family()) families.append(space::family_name(f));
  m.attr("MODELS") = py::tuple(families);

  m.def(
      "fit", &fit, py::arg("judgments"), py::arg("dims") = 2, py::kw_only(),
      py::arg("descriptors") = py::none(), py::arg("lam") = 0.0, py::arg("model") = "probit",
      py::arg("models") = std::vector<std::string>{}, py::arg("folds") = 5, py::arg("starts") = 16,
      py::arg("seed") = 1u, py::arg("bootstrap") = 0, py::arg("threads") = 0u,
      py::arg("progress") = py::none(),
      "Fits a space to triplet judgments (Judgments, from arrays or read_judgments; or a file in "
      "any "
      "format nibrig reads) as `nibrig space fit` does. descriptors: a catalog whose descriptors "
      "tie the "
      "axes (with lam > 0) and give the descriptor map; model: one of MODELS, or 'auto' to choose "
      "among "
      "`models` (default: all of MODELS) by `folds`-fold cross-validation (the table: "
      "Space.model_scores); "
      "starts: random starts of the fit, the best kept; seed: seeds the starts, the folds and the "
      "bootstrap, so one seed gives one space; bootstrap: resamples for confidence regions; "
      "threads: "
      "worker threads, 0 for one per core (the space does not depend on it); progress: called with "
      "(step, done, total). Releases the GIL; Ctrl-C stops it (KeyboardInterrupt).");
  m.def("default", [](int bootstrap, const py::object& progress) {
          if (bootstrap < 2) throw std::invalid_argument("bootstrap is " + std::to_string(bootstrap) + "; expected at least 2 resamples");
          Space out;
          run_long_call([&](std::stop_token stop, const Report& report) {
            model::design::DefaultsOptions options;
            options.bootstrap_resamples = bootstrap;
            options.stop = stop;
            options.progress = report;
            auto cached = model::design::default_space(options);
            out.file = std::move(cached.value.space);
            out.warnings = std::move(cached.warnings);
          }, progress);
          return out;
        }, py::kw_only(), py::arg("bootstrap") = 200, py::arg("progress") = py::none(),
        "The space the demo and the panel open on: a SIMULATED observer's judgments of the bundled catalog's "
        "tools (no human judgments ship with nibrig), with a descriptor map; computed once (seconds) and kept "
        "in the user cache");
  m.def(
      "load",
      [](const std::filesystem::path& file) {
        ReleasedGil unlocked;
        return Space{space::read_space_file(file), {}};
      },
      py::arg("path"), "Reads a space file (`nibrig space fit -o`)");
  add_space_scores(m);
}

}  // namespace nibrig::ui::python
