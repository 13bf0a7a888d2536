// The Python class nibrig.design.Designer as a C++ type, which the design area's files share.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>

#include "model/design/prediction_inputs.hpp"

namespace nibrig::ui::python {

struct Designer {
  std::shared_ptr<const model::design::PredictionInputs> inputs;  // setup points into it: it stays put
};

// Designer.modes and Designer.forcing, added to the submodule once Designer is registered.
void add_design_mechanics(pybind11::module_ m);
void add_forcing_calibration(pybind11::module_ m);
void add_material_calibration(pybind11::module_ m);
void add_design_loop(pybind11::module_ m);

}  // namespace nibrig::ui::python
