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
  return py::make_tuple(
      design_point_state(t.point), t.surface, t.design_name, t.first_mode_hz, modal_state(t.modal),
      t.response_magnitude, spectrum_state(t.spectrum), t.mu, descriptors_state(t.vibration),
      py::make_tuple(t.descriptor_errors.names, t.descriptor_errors.covariance,
                     t.descriptor_errors.vibration_samples, t.descriptor_errors.friction_samples),
      t.material_basis);
}

design::PredictedTool predicted_tool_of(const py::tuple& state) {
  const std::string type = "Prediction";
  require_state(state, 11, type);
  design::PredictedTool t;
  t.point = design_point_of(state[0], type);
  t.surface = state[1].cast<std::string>();
  t.design_name = state[2].cast<std::string>();
  t.first_mode_hz = state[3].cast<double>();
  t.modal = modal_of(state[4], type);
  t.response_magnitude = state[5].cast<std::vector<double>>();
  t.spectrum = spectrum_of(state[6], type);
  t.mu = state[7].cast<double>();
  t.vibration = descriptors_of(state[8], type);
  const auto errors = state[9].cast<py::tuple>();
  require_state(errors, 4, type);
  t.descriptor_errors = {errors[0].cast<std::vector<std::string>>(),
                         errors[1].cast<Eigen::MatrixXd>(), errors[2].cast<std::size_t>(),
                         errors[3].cast<std::size_t>()};
  t.material_basis = state[10].cast<std::string>();
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
