// The extension module c2f._c2f; the package c2f (python/c2f/__init__.py) is its front.

#include <pybind11/pybind11.h>

#include "model_energy.hpp"
#include "released_gil.hpp"

namespace c2f::python {
void bind_solve(pybind11::module_& module);
void bind_stereo(pybind11::module_& module);
void bind_segment(pybind11::module_& module);
void bind_lift(pybind11::module_& module);
}  // namespace c2f::python

PYBIND11_MODULE(_c2f, module) {
  module.doc() = "c2f: coarse-to-fine lifted MAP inference (the compiled core of the package)";
  c2f::python::bind_energy(module);
  c2f::python::bind_solve(module);
  c2f::python::bind_stereo(module);
  c2f::python::bind_segment(module);
  c2f::python::bind_lift(module);
  c2f::python::register_exit_hook();
}
