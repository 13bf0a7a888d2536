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
#include "model/space/space_inputs.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/numpy_views.hpp"
#include "ui/python/space_types.hpp"
#include "ui/python/submodules.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace space = model::space;

namespace {

Space fit(const py::object& judgments_or_path, std::size_t dims, const std::optional<std::filesystem::path>& descriptors,
          double lambda, const std::string& model, int starts, unsigned seed, int bootstrap, unsigned threads,
          const py::object& progress) {
  const bool read = py::isinstance<Judgments>(judgments_or_path);
  // A path or Judgments: anything else named, not pybind11's "Unable to cast".
  if (!read && !py::isinstance<py::str>(judgments_or_path) &&
      !py::isinstance(judgments_or_path, py::module_::import("os").attr("PathLike")))
    throw py::type_error("judgments: expected a file path or Judgments from read_judgments, found " +
                         std::string(py::str(judgments_or_path.get_type().attr("__name__"))));
  const std::filesystem::path judgments =
      read ? judgments_or_path.cast<const Judgments&>().file : judgments_or_path.cast<std::filesystem::path>();
  if (dims < 1) throw std::invalid_argument("dims is " + std::to_string(dims) + "; expected at least 1");
  if (starts < 1 || starts > space::kMostFitStarts)  // the library's bound, before the judgments are read
    throw std::invalid_argument("starts: " + std::to_string(starts) + ": expected a number of starts, 1 to " +
                                std::to_string(space::kMostFitStarts));
  if (bootstrap < 0) throw std::invalid_argument("bootstrap is " + std::to_string(bootstrap) + "; expected 0 or more");
  const std::filesystem::path catalog = descriptors.value_or(std::filesystem::path());
  space::SpaceFitSettings settings;
  settings.starts = starts;
  settings.seed = seed;
  settings.threads = threads;
  settings.bootstrap = bootstrap;
  settings.choose_model = model == "auto";
  if (!settings.choose_model) settings.model = space::parse_family(model);
  Space out;
  {
    py::gil_scoped_release unlocked;  // reading a large judgments file takes a moment too
    const auto in = read ? space::space_inputs(judgments_or_path.cast<const Judgments&>().set, catalog, dims, lambda)
                         : space::read_space_inputs(judgments, catalog, dims, lambda);
    py::gil_scoped_acquire locked;
    run_long_call(
        [&](std::stop_token stop, const Report& report) {
          settings.stop = stop;
          auto fitted = space::fit_space_file(in, judgments, catalog, settings, report);
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

py::array_t<double> predict_triplets(const Space& s, const std::vector<std::tuple<std::string, std::string, std::string>>& triplets) {
  py::array_t<double> p(static_cast<py::ssize_t>(triplets.size()));
  auto out = p.mutable_unchecked<1>();
  for (std::size_t k = 0; k < triplets.size(); ++k) {
    const auto& [reference, a, b] = triplets[k];
    out(static_cast<py::ssize_t>(k)) =
        space::probability_first(s.file.model, s.file.coordinates, s.index_of(reference), s.index_of(a), s.index_of(b));
  }
  return p;
}

Placement place(const Space& s, const py::object& descriptors, const std::optional<Eigen::MatrixXd>& error) {
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
  return {error ? space::place_from_descriptors(*s.file.descriptor_map, x, *error)
                : space::place_from_descriptors(*s.file.descriptor_map, x)};
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

}  // namespace

void add_space_module(py::module_ m) {
  py::class_<Placement>(m, "Placement", "A tool placed from its descriptors: a Gaussian position in the space")
      .def_property_readonly(
          "mean", [](const py::object& self) { return vector_view(self.cast<const Placement&>().placement.mean, self); },
          "Its position (one value per axis, in the space's units); a view, not a copy")
      .def_property_readonly(
          "covariance",
          [](const py::object& self) { return matrix_view(self.cast<const Placement&>().placement.covariance, self); },
          "The position's covariance (axes × axes, squared units): the map's scatter and its uncertainty")
      .def("ellipses", &ellipses, py::arg("levels") = std::vector<double>{0.68, 0.95},
           "The region in the plane of axes 1 and 2 at each level: (semi_axis_1, semi_axis_2, angle in radians "
           "from axis 1) per level");

  py::class_<Judgments>(m, "Judgments", "Triplet judgments read once, for several fits")
      .def_property_readonly("stimuli", [](const Judgments& j) { return j.set.stimuli; })
      .def_property_readonly("triplets", [](const Judgments& j) { return j.set.triplets.size(); })
      .def_property_readonly("responses", [](const Judgments& j) { return model::io::response_count(j.set); })
      .def_readonly("file", &Judgments::file);
  m.def("read_judgments", [](const std::filesystem::path& file) {
          py::gil_scoped_release unlocked;
          return Judgments{model::io::read_triplets(file), file};
        }, py::arg("path"), "Reads triplet judgments (the paper's, Lagunas', Salmon's formats) once, for several fits");

  py::class_<Space>(m, "Space", "A perceptual space fitted from triplet judgments (Sec. 4)")
      .def_property_readonly("stimuli", [](const Space& s) { return s.file.stimuli; }, "The judged stimuli, in order")
      .def_property_readonly("dims", [](const Space& s) { return static_cast<std::size_t>(s.file.coordinates.rows()); },
                             "Its number of axes")
      .def_property_readonly(
          "coordinates", [](const py::object& self) { return matrix_view(self.cast<const Space&>().file.coordinates, self); },
          "Each stimulus's position: an array of dims × stimuli, in the space's units (one unit of difference in "
          "distance is 75 % preference under the paper's model); a view, not a copy")
      .def_property_readonly("model", [](const Space& s) { return space::family_name(s.file.model.family); },
                             "The judgment model's family: 'probit' (the paper's), 'logistic', 'student-t', with "
                             "'+lapse' and '+noise'")
      .def_property_readonly("model_description", [](const Space& s) { return space::describe_model(s.file.model); })
      .def_property_readonly("model_reason", [](const Space& s) { return s.file.model_reason; },
                             "Why this model: given, or the cross-validation that chose it")
      .def_property_readonly("scale", [](const Space& s) { return s.file.model.scale; },
                             "The model's scale s: P = link(s · (d_b − d_a)) for distances in the space's units")
      .def_property_readonly("lapse", [](const Space& s) { return s.file.model.lapse; },
                             "The share of answers given at random (0 without a lapse)")
      .def_property_readonly("lam", [](const Space& s) { return s.file.lambda; },
                             "λ, the weight that tied the axes to the descriptors (0: none)")
      .def_property_readonly("negative_log_likelihood", [](const Space& s) { return s.file.negative_log_likelihood; },
                             "Of the judgments fitted, in nats")
      .def_property_readonly("responses", [](const Space& s) { return s.file.responses; })
      .def_property_readonly("descriptor_names", [](const Space& s) { return s.file.descriptor_names; })
      .def_property_readonly("has_descriptor_map", [](const Space& s) { return s.file.descriptor_map.has_value(); })
      .def_property_readonly("warnings", [](const Space& s) { return s.warnings; })
      .def("predict", &predict_triplets, py::arg("triplets"),
           "P(the first candidate is judged closer to the reference) for each (reference, first, second) of "
           "stimulus names, under the space's judgment model")
      .def("place", &place, py::arg("descriptors"), py::arg("error") = py::none(),
           "Places a tool from its descriptors (a dict by name, or values in descriptor_names' order) through the "
           "space's descriptor map; `error`, the descriptors' own covariance (a predicted design's), widens the region")
      .def("save", [](const Space& s, const std::filesystem::path& file) {
             py::gil_scoped_release unlocked;
             space::write_space_file(file, s.file);
           }, py::arg("path"), "Writes the space file (FORMATS.md 'Perceptual space'), atomically")
      .def("__repr__", [](const Space& s) {
        return "<nibrig.space.Space: " + std::to_string(s.file.coordinates.rows()) + "-D, " +
               std::to_string(s.file.stimuli.size()) + " stimuli, " + space::family_name(s.file.model.family) + ">";
      });

  m.def("fit", &fit, py::arg("judgments"), py::arg("dims") = 2, py::kw_only(), py::arg("descriptors") = py::none(),
        py::arg("lam") = 0.0, py::arg("model") = "probit", py::arg("starts") = 16, py::arg("seed") = 1u,
        py::arg("bootstrap") = 0, py::arg("threads") = 0u, py::arg("progress") = py::none(),
        "Fits a space to triplet judgments (a file in any format nibrig reads: the paper's, Lagunas', "
        "Salmon's; or Judgments from read_judgments) as "
        "`nibrig space fit` does. descriptors: a catalog whose descriptors tie the axes (with lam > 0) and "
        "give the descriptor map; model: a family name or 'auto' (chosen by cross-validation); bootstrap: "
        "resamples for confidence regions; progress: called with (step, done, total). Releases the GIL; "
        "Ctrl-C stops it (KeyboardInterrupt).");
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
  m.def("load", [](const std::filesystem::path& file) {
          py::gil_scoped_release unlocked;
          return Space{space::read_space_file(file), {}};
        }, py::arg("path"), "Reads a space file (`nibrig space fit -o`)");
  add_space_scores(m);
}

}  // namespace nibrig::ui::python
