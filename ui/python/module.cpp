// nibrig's Python face (`import nibrig`): the compiled part, nibrig._core, one submodule per area.
// The package around it (ui/python/nibrig/) re-exports the submodules and carries their type
// hints (.pyi files, whose docstrings the build copies from here: ui/python/pyi_docstrings.py).
#include <pybind11/pybind11.h>

#include "ui/python/errors.hpp"
#include "ui/python/python_log.hpp"
#include "ui/python/submodules.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "nibrig's library calls: the compiled part of the nibrig package";
  nibrig::ui::python::register_error_translation();
  nibrig::ui::python::install_python_log();
  m.attr("__version__") = NIBRIG_VERSION;
  nibrig::ui::python::add_space_module(m.def_submodule("space", "Perceptual spaces: fit, predict, place"));
  nibrig::ui::python::add_measure_module(
      m.def_submodule("measure", "Recordings to friction, spectra and descriptors; catalogs"));
  nibrig::ui::python::add_design_module(
      m.def_submodule("design", "Predict designs, place them, search for the nearest one"));
  nibrig::ui::python::add_render_module(
      m.def_submodule("render", "Tools rendered offline through the real-time engine into arrays"));
  nibrig::ui::python::add_rig_module(
      m.def_submodule("rig", "The turntable rig: capture sessions, compare with the simulation, read sessions"));
  nibrig::ui::python::add_study_module(m.def_submodule("study", "Triplet studies: their answers and their report"));
  nibrig::ui::python::add_audition_module(
      m.def_submodule("audition", "Tools played live on an audio device, speed and force set as they play"));
}
