// Each area of the module adds its functions and classes to its submodule.
#pragma once

#include <pybind11/pybind11.h>

namespace nibrig::ui::python {

void add_space_module(pybind11::module_ m);
void add_measure_module(pybind11::module_ m);
void add_design_module(pybind11::module_ m);
void add_render_module(pybind11::module_ m);
void add_rig_module(pybind11::module_ m);
void add_study_module(pybind11::module_ m);
void add_audition_module(pybind11::module_ m);

}  // namespace nibrig::ui::python
