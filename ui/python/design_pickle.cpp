// How a predicted design and a Designer pickle, so that joblib or multiprocessing can hand them to
// a worker and back: a prediction as its numbers, a Designer as its forcing model and the files it
// read, which must still hold what they held.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>

#include "model/forcing/forcing_file.hpp"
#include "model/io/bounded_read.hpp"
#include "ui/python/design_types.hpp"
#include "ui/python/pickle_state.hpp"
#include "ui/python/python_log.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace design = model::design;

namespace {

constexpr const char* kPickledDesigner = "a pickled nibrig.design.Designer";

// A template or material table as the Designer read it: small text files.
std::string file_text(const std::filesystem::path& file) {
  return model::io::read_bounded_file(file, std::size_t{16} << 20, "a design input", "a few KiB");
}

}  // namespace

py::tuple predicted_tool_state(const design::PredictedTool& t) {
  std::vector<py::tuple> mix;
  for (const auto& share : t.point.mix)
    mix.push_back(py::make_tuple(share.material, share.fraction));
  return py::make_tuple(
      mix, t.point.tip_diameter_m, t.surface, t.design_name, t.first_mode_hz,
      py::make_tuple(t.modal.omega, t.modal.zeta, t.modal.input, t.modal.output),
      t.response_magnitude,
      py::make_tuple(t.spectrum.frequencies_hz, t.spectrum.speeds_m_s, t.spectrum.amplitude_m_s2),
      t.mu,
      py::make_tuple(t.vibration.weighted_mean, t.vibration.weighted_power,
                     t.vibration.band_energies),
      py::make_tuple(t.descriptor_errors.names, t.descriptor_errors.covariance,
                     t.descriptor_errors.vibration_samples, t.descriptor_errors.friction_samples),
      t.material_basis);
}

design::PredictedTool predicted_tool_of(const py::tuple& state) {
  require_state(state, 12, "Prediction");
  design::PredictedTool t;
  for (const auto& share : state[0].cast<std::vector<std::pair<std::string, double>>>())
    t.point.mix.push_back({share.first, share.second});
  t.point.tip_diameter_m = state[1].cast<double>();
  t.surface = state[2].cast<std::string>();
  t.design_name = state[3].cast<std::string>();
  t.first_mode_hz = state[4].cast<double>();
  const auto modal = state[5].cast<py::tuple>();
  t.modal = {modal[0].cast<std::vector<double>>(), modal[1].cast<std::vector<double>>(),
             modal[2].cast<std::vector<double>>(), modal[3].cast<std::vector<double>>()};
  t.response_magnitude = state[6].cast<std::vector<double>>();
  const auto spectrum = state[7].cast<py::tuple>();
  t.spectrum = {spectrum[0].cast<std::vector<double>>(), spectrum[1].cast<std::vector<double>>(),
                spectrum[2].cast<std::vector<std::vector<double>>>()};
  t.mu = state[8].cast<double>();
  const auto vibration = state[9].cast<py::tuple>();
  t.vibration = {vibration[0].cast<double>(), vibration[1].cast<double>(),
                 vibration[2].cast<std::map<int, std::vector<double>>>()};
  const auto errors = state[10].cast<py::tuple>();
  t.descriptor_errors = {errors[0].cast<std::vector<std::string>>(),
                         errors[1].cast<Eigen::MatrixXd>(), errors[2].cast<std::size_t>(),
                         errors[3].cast<std::size_t>()};
  t.material_basis = state[11].cast<std::string>();
  return t;
}

py::tuple designer_state(const Designer& d) {
  const auto& in = *d.inputs;
  return py::make_tuple(in.catalog_file, in.design_template_file, in.materials_file, in.setup.modes,
                        in.setup.mesh_size,
                        model::forcing::forcing_model_text(in.model, kPickledDesigner),
                        model::io::catalog_text(in.catalog, kPickledDesigner),
                        file_text(in.design_template_file), file_text(in.materials_file));
}

Designer designer_of(const py::tuple& state) {
  require_state(state, 9, "Designer");
  model::forcing::ForcingInputOptions options;
  options.catalog = state[0].cast<std::filesystem::path>();
  options.design_template = state[1].cast<std::filesystem::path>();
  options.materials = state[2].cast<std::filesystem::path>();
  options.modes = state[3].cast<int>();
  options.mesh_size = state[4].cast<double>();
  const auto forcing_text = state[5].cast<std::string>();
  const auto catalog_text = state[6].cast<std::string>();
  const auto template_text = state[7].cast<std::string>(),
             materials_text = state[8].cast<std::string>();
  Designer out;
  ReleasedGil unlocked;
  // The model travels whole (a default one need not be fitted again in the worker); the files
  // are read again where they are, and must still hold what they held when it was pickled.
  out.inputs = design::load_prediction_inputs(
      options, {}, model::forcing::parse_forcing_model(forcing_text, kPickledDesigner));
  const auto changed = [](const std::filesystem::path& file) {
    return std::invalid_argument(file.string() +
                                 " changed since this Designer was pickled: make a new one with "
                                 "nibrig.design.designer()");
  };
  if (model::io::catalog_text(out.inputs->catalog, kPickledDesigner) != catalog_text)
    throw changed(options.catalog);
  if (file_text(options.design_template) != template_text) throw changed(options.design_template);
  if (file_text(options.materials) != materials_text) throw changed(options.materials);
  return out;
}

}  // namespace nibrig::ui::python
