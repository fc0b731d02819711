#pragma once
// Arrays from Python checked at the boundary: every refusal is a TypeError or ValueError naming
// the argument and what was expected, never a crash or a silent conversion of wrong data.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "c2f/core/default_init_allocator.hpp"
#include "c2f/core/labeling.hpp"

namespace c2f::python {

namespace py = pybind11;

/// `object` as a numpy array: a numpy array as it is, a list or tuple (nested lists included) as
/// numpy makes it. Throws TypeError naming `name` and `what` was expected for anything else, for
/// a sequence numpy cannot make an array of (a ragged nested list), and for an object array
/// (entries that are not numbers). Every array argument of the package passes through here.
py::array array_argument(const py::handle& object, const std::string& name,
                         const std::string& what);

/// `object` as an integer in [lowest, highest]: a Python int or a numpy integer (a bool is
/// refused). Throws TypeError naming `name` for anything else, ValueError naming `name` and the
/// range when it lies outside it (however large).
long long integer_argument(const py::handle& object, const std::string& name, long long lowest,
                           long long highest);

/// `object` as a finite real number: a Python int or float, or a numpy number. Throws TypeError
/// naming `name` for anything else (a str, a bool, None), ValueError for NaN or infinity.
double real_argument(const py::handle& object, const std::string& name);

/// The entries of a float array and its shape.
struct RealArray {
  std::vector<double> values;  ///< row-major
  std::vector<py::ssize_t> shape;
};

/// Unary costs as the caller gave them: a float32 array kept in single precision (what
/// PairwiseEnergy::with_float_unaries stores), a float64 array in double.
struct CostArray {
  bool single_precision = false;
  std::vector<double> doubles;  ///< row-major, unless single_precision
  c2f::FloatValues floats;      ///< row-major, when single_precision
  std::vector<py::ssize_t> shape;
};

/// The entries of `object` as doubles, converted in one pass (no intermediate array; the GIL
/// released while it runs). Throws TypeError naming `name` unless it is a float32 or float64
/// numpy array, ValueError unless it has `ndim` dimensions (described by `shape`, e.g.
/// "(H, W, L)"), is not empty, and every entry is finite. Strided arrays are read in order.
RealArray float_values(const py::handle& object, const std::string& name, int ndim,
                       const std::string& shape);

/// float_values for unary costs: a float32 array is kept in single precision (half the memory;
/// every energy and reduction sums the same values in double as a widened copy would).
CostArray cost_array(const py::handle& object, const std::string& name, int ndim,
                     const std::string& shape);

/// `object` as a C-contiguous int64 array with `ndim` dimensions. Throws TypeError naming `name`
/// unless it is an integer numpy array (or a list of integers), ValueError unless it has `ndim`
/// dimensions (described by `shape`).
py::array_t<std::int64_t, py::array::c_style> integer_array(const py::handle& object,
                                                            const std::string& name, int ndim,
                                                            const std::string& shape);

/// The labeling `object` of `num_variables` variables with labels in [0, num_labels), given
/// flat (N,) or in `shape` (e.g. the grid's (H, W)). Throws TypeError or ValueError naming
/// `name`.
Labeling labeling_from(const py::handle& object, const std::string& name, std::size_t num_variables,
                       int num_labels, const std::vector<py::ssize_t>& shape);

/// `labeling` as an int32 array of `shape` (empty: flat).
py::array_t<std::int32_t> labeling_array(const Labeling& labeling,
                                         const std::vector<py::ssize_t>& shape);

/// "(3, 4, 5)"; "(3,)" for one dimension.
std::string shape_text(const std::vector<py::ssize_t>& shape);
std::string shape_text(const py::array& array);

}  // namespace c2f::python
