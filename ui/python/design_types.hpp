// The Python class nibrig.design.Designer as a C++ type, which the design area's files share.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>

#include "model/design/prediction_inputs.hpp"

namespace nibrig::ui::python {

struct Designer {
  std::shared_ptr<const model::design::PredictionInputs> inputs;  // setup points into it: it stays put
};

// How a predicted tool and a Designer pickle (design_pickle.cpp): the state and its reading back,
// which throws ValueError for a state that is not one, or a Designer whose files changed.
pybind11::tuple predicted_tool_state(const model::design::PredictedTool& tool);
model::design::PredictedTool predicted_tool_of(const pybind11::tuple& state);
pybind11::tuple designer_state(const Designer& designer);
Designer designer_of(const pybind11::tuple& state);

// Designer.modes and Designer.forcing, added to the submodule once Designer is registered.
void add_design_mechanics(pybind11::module_ m);
void add_forcing_calibration(pybind11::module_ m);
void add_material_calibration(pybind11::module_ m);
void add_design_loop(pybind11::module_ m);

}  // namespace nibrig::ui::python
