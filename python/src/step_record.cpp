#include "step_record.hpp"

#include <pybind11/numpy.h>

#include "numpy_input.hpp"
#include "released_gil.hpp"

namespace c2f::python {

namespace py = pybind11;

StepRecord::StepRecord(py::object callback, std::vector<py::ssize_t> shape)
    : callback_(std::move(callback)), shape_(std::move(shape)) {}

StepRecord::~StepRecord() {
  // Only when result() did not hand the exception back (it threw before): drop it.
  Py_XDECREF(error_type_);
  Py_XDECREF(error_value_);
  Py_XDECREF(error_traceback_);
}

ObserverDecision StepRecord::operator()(const StepEvent& event) {
  time_.push_back(event.time_s);
  energy_.push_back(event.energy);
  level_.push_back(event.level);
  step_.push_back(event.step);
  variables_.push_back(event.num_variables);
  step_variables_.push_back(event.step_variables);
  if (interpreter_exiting()) return ObserverDecision::stop;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) return stop_for_python_error();
  if (callback_.is_none()) return ObserverDecision::continue_run;
  try {
    py::dict info;
    info["time"] = event.time_s;
    info["level"] = event.level;
    info["step"] = event.step;
    info["energy"] = event.energy;
    info["variables"] = event.num_variables;
    info["step_variables"] = event.step_variables;
    info["at_original"] = event.at_original;
    info["labeling"] = labeling_array(event.ground_labeling(), shape_);
    const py::object answer = callback_(info);
    if (answer.is_none()) return ObserverDecision::continue_run;
    const bool is_bool = py::isinstance<py::bool_>(answer) ||
                         py::isinstance(answer, py::module_::import("numpy").attr("bool_"));
    if (!is_bool) {
      throw py::type_error("callback: expected True, False or None as its answer, got " +
                           std::string(py::str(py::type::of(answer).attr("__name__"))));
    }
    if (!answer.cast<bool>()) return ObserverDecision::stop;
  } catch (py::error_already_set& error) {
    error.restore();
    return stop_for_python_error();
  } catch (py::builtin_exception& error) {
    error.set_error();
    return stop_for_python_error();
  }
  return ObserverDecision::continue_run;
}

ObserverDecision StepRecord::stop_for_python_error() {
  PyErr_Fetch(&error_type_, &error_value_, &error_traceback_);
  PyErr_NormalizeException(&error_type_, &error_value_, &error_traceback_);
  return ObserverDecision::stop;
}

py::dict StepRecord::result(const Summary& summary, const std::string& report) {
  py::dict result;
  result["labeling"] = labeling_array(summary.labeling, shape_);
  result["energy"] = summary.energy;
  result["reason"] = std::string(to_string(summary.reason));
  result["seconds"] = summary.seconds;
  result["steps"] = summary.total_steps;
  result["summary"] = report;
  const auto size = [](const auto& values) { return static_cast<py::ssize_t>(values.size()); };
  py::dict trace;
  trace["time"] = py::array_t<double>(size(time_), time_.data());
  trace["level"] = py::array_t<int>(size(level_), level_.data());
  trace["step"] = py::array_t<long>(size(step_), step_.data());
  trace["energy"] = py::array_t<double>(size(energy_), energy_.data());
  trace["variables"] = py::array_t<std::size_t>(size(variables_), variables_.data());
  trace["step_variables"] = py::array_t<std::size_t>(size(step_variables_), step_variables_.data());
  result["trace"] = trace;
  if (error_type_ != nullptr) {
    if (error_value_ != nullptr) PyObject_SetAttrString(error_value_, "result", result.ptr());
    PyErr_Restore(error_type_, error_value_, error_traceback_);  // steals the references
    error_type_ = error_value_ = error_traceback_ = nullptr;
    throw py::error_already_set();
  }
  return result;
}

}  // namespace c2f::python
