// nibrig.design: a design point predicted on a surface (Sec. 5.3, as `nibrig predict`), placed in
// a space, and the searches for the design nearest a target or a group (Sec. 6.2 and 7, as `nibrig
// design`), within constraints. A Designer reads (or fits, the first time) what predicting needs
// once; each prediction then solves the design's FEM (about a second).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "model/design/design_grid_file.hpp"
#include "model/design/design_search.hpp"
#include "model/design/design_search_request.hpp"
#include "model/design/prediction_inputs.hpp"
#include "model/numeric/cancellation.hpp"
#include "ui/python/design_types.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/numpy_views.hpp"
#include "ui/python/pickle_state.hpp"
#include "ui/python/space_types.hpp"
#include "ui/python/submodules.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace design = model::design;

namespace {

struct Prediction {
  design::PredictedTool tool;
};

struct Search {
  design::SearchResult result;
  std::vector<std::string> targets;
  // Through a design grid: per candidate, whether the FEM solved it, and the grid's error measured.
  std::vector<bool> fem_solved;
  std::optional<double> grid_error;
};

Designer make_designer(const std::optional<std::filesystem::path>& catalog, const std::optional<std::filesystem::path>& forcing,
                       const std::optional<std::filesystem::path>& design_template,
                       const std::optional<std::filesystem::path>& materials, int modes, double mesh_size,
                       const py::object& progress) {
  model::forcing::ForcingInputOptions options;
  options.catalog = catalog.value_or(std::filesystem::path());
  options.design_template = design_template.value_or(std::filesystem::path());
  options.materials = materials.value_or(std::filesystem::path());
  options.modes = modes;
  options.mesh_size = mesh_size;
  model::forcing::check_forcing_input_options(options);  // the library's ranges, before the long call
  Designer out;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        // The default forcing model is fitted once (its designs simulated) and kept in the user cache.
        out.inputs = design::load_prediction_inputs(
            options, forcing.value_or(std::filesystem::path()), std::nullopt,
            [&](const model::forcing::DesignResponse&, std::size_t done, std::size_t total) {
              model::numeric::throw_if_cancelled(stop, "forcing model fit");
              report("simulating the forcing model's designs", done, total);
            });
      },
      progress);
  return out;
}

Prediction predict_design(const Designer& d, const std::string& point, const std::string& surface) {
  Prediction out;
  run_long_call([&](std::stop_token, const Report&) {
    out.tool = design::predict_tool(d.inputs->setup, design::parse_design_point(point), surface);
  }, py::none());
  return out;
}

// A target: a stimulus of the space by name (judged: exactly there), or a Placement.
model::space::Placement target_of(const Space& s, const py::handle& target, std::string& name) {
  if (py::isinstance<py::str>(target)) {
    name = target.cast<std::string>();
    const auto i = s.index_of(name);
    model::space::Placement p;
    p.mean = s.file.coordinates.col(static_cast<Eigen::Index>(i));
    p.covariance = Eigen::MatrixXd::Zero(p.mean.size(), p.mean.size());
    return p;
  }
  name = "placed target";
  return target.cast<const Placement&>().placement;
}

// The request's fields as this call's arguments.
std::string search_argument(design::DesignSearchField field) {
  return field == design::DesignSearchField::mix ? "mix_a, mix_b" : design::field_name(field);
}

Search search_designs(const Designer& d, const Space& s, const py::object& targets,
                      const std::string& surface,
                      const std::optional<std::pair<std::string, std::string>>& between,
                      const std::string& aim, const std::optional<double>& min_tip_mm,
                      const std::optional<double>& max_tip_mm,
                      const std::vector<std::string>& allow,
                      const std::map<std::string, double>& cost,
                      const std::optional<double>& max_cost, const std::string& mix_a,
                      const std::string& mix_b, bool through_grid, const py::object& progress) {
  design::DesignSearchRequest request;
  request.targets = [&] {
    design::DesignSearchTargets out{s.file.descriptor_map, {}, {}};
    const py::list listed =
        py::isinstance<py::str>(targets) || !py::isinstance<py::sequence>(targets)
            ? py::list(py::make_tuple(targets))
            : py::list(targets);
    for (const auto& t : listed) {
      std::string name;
      out.placements.push_back(target_of(s, t, name));
      out.names.push_back(name);
    }
    return out;
  };
  request.surface = surface;
  request.aim = design::parse_group_aim(aim, search_argument);
  if (min_tip_mm) request.constraints.min_tip_m = *min_tip_mm * 1e-3;
  if (max_tip_mm) request.constraints.max_tip_m = *max_tip_mm * 1e-3;
  request.constraints.materials = allow;
  request.constraints.cost = cost;
  request.constraints.max_cost = max_cost;
  if (between)
    request.between.emplace(design::parse_design_point(between->first),
                            design::parse_design_point(between->second));
  request.first_material = mix_a, request.second_material = mix_b;
  // Refused as a ValueError naming the argument, before any prediction.
  const design::DesignSearch search(std::move(request), search_argument);
  Search out;
  out.targets = search.targets().names;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        const design::SearchProgress counted = [&](const design::Candidate&, std::size_t done, std::size_t total) {
          report("predicting designs", done, total);
        };
        if (!through_grid) {
          out.result = search.run(*d.inputs, stop, counted).result;
          return;
        }
        const auto grid = design::cached_design_response_grid(
            *d.inputs, design::default_grid_axes(*d.inputs, mix_a, mix_b),
            [&](std::size_t done, std::size_t total) {
              report("solving the design grid", done, total);
            },
            stop);
        auto searched = search.run(*d.inputs, grid, stop, counted);
        out.result = std::move(searched.result);
        out.fem_solved = std::move(searched.fem_solved);
        out.grid_error = searched.grid_error;
      },
      progress);
  return out;
}

py::dict candidate_dict(const design::Candidate& c, const std::vector<std::string>& targets) {
  py::dict d;
  d["design"] = design::to_string(c.point);
  d["distance"] = c.distance, d["distance_sd"] = c.distance_sd;
  d["mu"] = c.mu, d["weighted_mean"] = c.weighted_mean;
  d["coordinates"] = std::vector<double>(c.placement.mean.data(), c.placement.mean.data() + c.placement.mean.size());
  py::dict each;
  for (std::size_t t = 0; t < targets.size() && t < c.target_distances.size(); ++t)
    each[py::str(targets[t])] = py::make_tuple(c.target_distances[t], c.target_distance_sds[t]);
  d["to_targets"] = each;
  return d;
}

// A search as its candidates' values, bit for bit; each placement pickles as a Placement does.
py::tuple search_state(const Search& s) {
  py::list candidates;
  for (const auto& c : s.result.evaluated)
    candidates.append(py::make_tuple(design_point_state(c.point), py::cast(Placement{c.placement}),
                                     c.mu, c.weighted_mean, c.distance, c.distance_sd,
                                     c.target_distances, c.target_distance_sds, c.score));
  return py::make_tuple(candidates, s.result.ranked, s.targets, s.fem_solved, s.grid_error);
}

Search search_of(const py::tuple& state) {
  require_state(state, 5, "Search");
  Search s;
  for (const auto& item : state[0].cast<py::list>()) {
    const auto t = item.cast<py::tuple>();
    require_state(t, 9, "Search");
    design::Candidate c;
    c.point = design_point_of(t[0], "Search");
    c.placement = t[1].cast<const Placement&>().placement;
    c.mu = t[2].cast<double>(), c.weighted_mean = t[3].cast<double>();
    c.distance = t[4].cast<double>(), c.distance_sd = t[5].cast<double>();
    c.target_distances = t[6].cast<std::vector<double>>();
    c.target_distance_sds = t[7].cast<std::vector<double>>();
    c.score = t[8].cast<std::optional<double>>();
    s.result.evaluated.push_back(std::move(c));
  }
  s.result.ranked = state[1].cast<std::vector<std::size_t>>();
  s.targets = state[2].cast<std::vector<std::string>>();
  s.fem_solved = state[3].cast<std::vector<bool>>();
  s.grid_error = state[4].cast<std::optional<double>>();
  if (!s.fem_solved.empty() && s.fem_solved.size() != s.result.evaluated.size())
    throw std::invalid_argument("Search: not a pickled Search");
  // best() and runners_up() index the candidates with these.
  for (const auto k : s.result.ranked)
    if (k >= s.result.evaluated.size()) throw std::invalid_argument("Search: not a pickled Search");
  if (s.result.ranked.empty()) throw std::invalid_argument("Search: not a pickled Search");
  return s;
}

}  // namespace

void add_design_module(py::module_ m) {
  py::class_<Prediction>(m, "Prediction",
                         "A design predicted on a surface, as `nibrig predict` gives it")
      .def_property_readonly("design",
                             [](const Prediction& p) { return design::to_string(p.tool.point); })
      .def_property_readonly("surface", [](const Prediction& p) { return p.tool.surface; })
      .def_property_readonly(
          "mu", [](const Prediction& p) { return p.tool.mu; }, "Predicted Coulomb friction")
      .def_property_readonly("first_mode_hz",
                             [](const Prediction& p) { return p.tool.first_mode_hz; })
      .def_property_readonly(
          "mode_frequencies_hz",
          [](const Prediction& p) {
            std::vector<double> f;
            for (double w : p.tool.modal.omega) f.push_back(w / (2 * std::numbers::pi));
            return f;
          },
          "The design's modes, undamped, Hz")
      .def_property_readonly("frequencies_hz",
                             [](const Prediction& p) { return p.tool.spectrum.frequencies_hz; })
      .def_property_readonly("speeds_m_s",
                             [](const Prediction& p) { return p.tool.spectrum.speeds_m_s; })
      .def_property_readonly(
          "amplitude", [](const Prediction& p) { return spectrum_array(p.tool.spectrum); },
          "Predicted velocity-binned spectrum, speeds x frequencies, m/s²")
      .def_property_readonly("weighted_mean",
                             [](const Prediction& p) { return p.tool.vibration.weighted_mean; })
      .def(
          "place",
          [](const Prediction& p, const Space& s) {
            if (!s.file.descriptor_map)
              throw std::invalid_argument("the space has no descriptor map");
            return Placement{design::place_predicted(*s.file.descriptor_map, p.tool)};
          },
          py::arg("space"),
          "Where it lies in a space with a descriptor map, its descriptors' error included")
      .def(py::pickle([](const Prediction& p) { return predicted_tool_state(p.tool); },
                      [](const py::tuple& state) { return Prediction{predicted_tool_of(state)}; }));

  py::class_<Search>(m, "Search",
                     "A design search: every candidate, the optimum and its runners-up")
      .def_property_readonly(
          "optimum", [](const Search& s) { return candidate_dict(s.result.best(), s.targets); })
      .def_property_readonly(
          "path",
          [](const Search& s) {
            py::list out;
            for (const auto& c : s.result.evaluated) out.append(candidate_dict(c, s.targets));
            return out;
          },
          "Every candidate in the order evaluated")
      .def_property_readonly(
          "fem_solved", [](const Search& s) { return s.fem_solved; },
          "Through the design grid (grid=True): per candidate of the path, whether the FEM solved "
          "it "
          "(else its numbers are the grid's); empty when every candidate was solved")
      .def_property_readonly(
          "grid_error", [](const Search& s) { return s.grid_error; },
          "Through the design grid: its placement error measured at the cells of the designs that "
          "could "
          "be the optimum, in space units; None otherwise")
      .def(
          "runners_up",
          [](const Search& s, std::size_t count) {
            py::list out;
            for (auto k : s.result.runners_up(count))
              out.append(candidate_dict(s.result.evaluated[k], s.targets));
            return out;
          },
          py::arg("count") = 4, "Up to `count` distinct designs after the optimum, nearest first")
      .def(py::pickle(&search_state, &search_of));

  py::class_<Designer>(m, "Designer", "What predicting designs needs, read once")
      .def("predict", &predict_design, py::arg("design"), py::arg("surface"),
           "Predicts a design point ('DM85:0.5,vero:0.5,tip=2mm') on a surface: solves its FEM, "
           "then its spectrum and μ")
      .def("search", &search_designs, py::arg("space"), py::arg("targets"), py::arg("surface"),
           py::kw_only(), py::arg("between") = py::none(), py::arg("aim") = "largest",
           py::arg("min_tip_mm") = py::none(), py::arg("max_tip_mm") = py::none(),
           py::arg("allow") = std::vector<std::string>{},
           py::arg("cost") = std::map<std::string, double>{}, py::arg("max_cost") = py::none(),
           py::arg("mix_a") = "vero", py::arg("mix_b") = "DM85", py::arg("grid") = false,
           py::arg("progress") = py::none(),
           "The design nearest the target (a stimulus name or a Placement) or a group of them "
           "(their largest or "
           "mean distance), along `between` (two design points) or over the two-material mix x "
           "fitted tips; "
           "tips in mm, `allow` the materials a printer may load, `cost` a proxy per material "
           "limited by "
           "`max_cost`. `grid=True` searches through the design grid (solved once, then kept) and "
           "solves the FEM only where its measured error could change the answer: seconds. "
           "Releases the GIL; Ctrl-C stops it.")
      .def(py::pickle(&designer_state, &designer_of));

  m.def("designer", &make_designer, py::kw_only(), py::arg("catalog") = py::none(), py::arg("forcing") = py::none(),
        py::arg("template") = py::none(), py::arg("materials") = py::none(), py::arg("modes") = 0,
        py::arg("mesh_size") = 0.0, py::arg("progress") = py::none(),
        "Reads what predicting needs: the catalog (default: bundled), the forcing model (default: fitted to the "
        "catalog once and kept in the user cache), the stylus template and materials; modes and mesh_size (m) "
        "as the template's when 0.");
  add_design_mechanics(m);
  add_forcing_calibration(m);
  add_material_calibration(m);
  add_design_loop(m);
}

}  // namespace nibrig::ui::python
