// The extension module c2f._c2f; the package c2f (python/c2f/__init__.py) is its front.

#include <pybind11/pybind11.h>

#include <cstring>
#include <exception>
#include <stdexcept>

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
  // A C++ message that is not UTF-8 (a file's bytes quoted in it) still reaches Python, with the
  // odd bytes as \xNN: pybind11's own translation raised the exception with an empty message.
  pybind11::register_exception_translator([](std::exception_ptr raised) {
    const auto set = [](PyObject* type, const char* message) {
      PyObject* text = PyUnicode_DecodeUTF8(message, static_cast<Py_ssize_t>(std::strlen(message)),
                                            "backslashreplace");
      PyErr_SetObject(type, text);
      Py_XDECREF(text);
    };
    try {
      std::rethrow_exception(raised);
    } catch (const pybind11::builtin_exception&) {
      throw;  // pybind11's own (type_error, value_error, ...): its translation
    } catch (const std::invalid_argument& error) {
      set(PyExc_ValueError, error.what());
    } catch (const std::runtime_error& error) {
      set(PyExc_RuntimeError, error.what());
    }
  });
}
