#pragma once
// The observer of a run started from Python: it records every step without the GIL, shows each
// to the caller's callback (which may stop the run) and honours Ctrl-C; after the run it turns
// the Summary into the dict c2f.Result is made of, or raises the Python exception that stopped
// the run with that dict attached as `result`.

#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>
#include <vector>

#include "c2f/driver/observer.hpp"
#include "c2f/driver/summary.hpp"

namespace c2f::python {

class StepRecord {
 public:
  /// `callback` (None: none) is called after every step with a dict (time, level, step,
  /// energy, variables, step_variables, at_original, labeling: the original variables' labeling
  /// this step stands for, in `shape`, O(N) per step); a False answer stops the run, and an answer
  /// other than True, False or None stops it with a TypeError naming the callback. The run also
  /// stops at its next step once the interpreter begins to exit (released_gil.hpp). `shape` is the
  /// labeling's array shape (empty: flat).
  StepRecord(pybind11::object callback, std::vector<pybind11::ssize_t> shape);
  ~StepRecord();
  StepRecord(const StepRecord&) = delete;
  StepRecord& operator=(const StepRecord&) = delete;

  /// The observer; called with the GIL released (it takes it for the callback and signals).
  ObserverDecision operator()(const StepEvent& event);

  /// The run's result as a dict (labeling in the shape), with `report` as its summary. Throws
  /// pybind11::error_already_set, after attaching the dict as `result`, when a Python
  /// exception (KeyboardInterrupt, the callback's own) stopped the run. Call with the GIL.
  pybind11::dict result(const Summary& summary, const std::string& report);

 private:
  ObserverDecision stop_for_python_error();

  std::vector<double> time_, energy_;
  std::vector<int> level_;
  std::vector<long> step_;
  std::vector<std::size_t> variables_;
  std::vector<std::size_t> step_variables_;
  pybind11::object callback_;
  std::vector<pybind11::ssize_t> shape_;
  PyObject* error_type_ = nullptr;  ///< the fetched exception (owned references)
  PyObject* error_value_ = nullptr;
  PyObject* error_traceback_ = nullptr;
};

}  // namespace c2f::python
