#include "numpy_input.hpp"

#include <cmath>

#include "c2f/support/text_input.hpp"
#include "released_gil.hpp"

namespace c2f::python {

std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::string text = "(";
  for (std::size_t d = 0; d < shape.size(); ++d) text += (d ? ", " : "") + std::to_string(shape[d]);
  return text + (shape.size() == 1 ? ",)" : ")");
}

std::string shape_text(const py::array& array) {
  return shape_text(std::vector<py::ssize_t>(array.shape(), array.shape() + array.ndim()));
}

py::array array_argument(const py::handle& object, const std::string& name,
                         const std::string& what) {
  py::array array;
  if (py::isinstance<py::array>(object)) {
    array = py::reinterpret_borrow<py::array>(object);
  } else if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object)) {
    try {
      array = py::module_::import("numpy").attr("asarray")(object);
    } catch (py::error_already_set& error) {
      throw py::type_error(name + ": expected " + what + "; numpy cannot make one array of this " +
                           std::string(py::str(py::type::of(object).attr("__name__"))) +
                           " (a nested list must be rectangular): " + error.what());
    }
  } else {
    throw py::type_error(name + ": expected " + what + ", got " +
                         std::string(py::str(py::type::of(object).attr("__name__"))));
  }
  if (array.dtype().kind() == 'O') {
    throw py::type_error(name + ": expected " + what +
                         ", got an object array (a ragged nested list, or entries that are not "
                         "numbers)");
  }
  return array;
}

namespace {

std::string type_name(const py::handle& object) {
  return py::str(py::type::of(object).attr("__name__"));
}

/// Whether `object` is an integer Python or numpy accepts as an index (int, numpy integers),
/// not a bool.
bool is_integer(const py::handle& object) {
  if (py::isinstance<py::bool_>(object)) return false;
  const py::object numpy_bool = py::module_::import("numpy").attr("bool_");
  if (py::isinstance(object, numpy_bool)) return false;
  return PyIndex_Check(object.ptr()) != 0;
}

}  // namespace

long long integer_argument(const py::handle& object, const std::string& name, long long lowest,
                           long long highest) {
  const std::string range = "[" + std::to_string(lowest) + ", " + std::to_string(highest) + "]";
  if (!is_integer(object)) {
    throw py::type_error(name + ": expected an integer in " + range + ", got " + type_name(object));
  }
  const py::int_ value = py::reinterpret_steal<py::int_>(PyNumber_Index(object.ptr()));
  if (!value) throw py::error_already_set();
  int overflow = 0;
  const long long result = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
  if (overflow != 0 || result < lowest || result > highest) {
    throw py::value_error(name + ": expected an integer in " + range + ", got " +
                          printable(std::string(py::str(py::handle(value))), 40));
  }
  return result;
}

double real_argument(const py::handle& object, const std::string& name) {
  const py::object numpy_number = py::module_::import("numpy").attr("number");
  const bool number =
      !py::isinstance<py::bool_>(object) &&
      (PyFloat_Check(object.ptr()) || PyLong_Check(object.ptr()) ||
       (py::isinstance(object, numpy_number) &&
        !py::isinstance(object, py::module_::import("numpy").attr("complexfloating"))));
  if (!number) throw py::type_error(name + ": expected a real number, got " + type_name(object));
  const double value = PyFloat_AsDouble(object.ptr());
  if (value == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    throw py::value_error(name + ": expected a real number, got " +
                          printable(std::string(py::str(object)), 40));
  }
  if (!std::isfinite(value))
    throw py::value_error(name + ": expected a finite number, got " +
                          printable(std::string(py::str(object)), 40));
  return value;
}

namespace {

void require_shape(const py::array& array, const std::string& name, int ndim,
                   const std::string& shape) {
  if (array.ndim() != ndim) {
    throw py::value_error(name + ": expected an array of shape " + shape + ", got shape " +
                          shape_text(array));
  }
  if (array.size() == 0) {
    throw py::value_error(name + ": expected a non-empty array of shape " + shape + ", got shape " +
                          shape_text(array));
  }
}

}  // namespace

namespace {

/// Copies and checks `count` entries; returns the index of the first non-finite one, or
/// `count`.
template <class T, class Out>
std::size_t copy_finite(const T* data, std::size_t count, Out* out) {
  std::size_t bad = count;
  for (std::size_t i = 0; i < count; ++i) {
    const Out value = static_cast<Out>(data[i]);
    out[i] = value;
    if (!std::isfinite(value) && bad == count) bad = i;
  }
  return bad;
}

/// The float array `object` after its dtype and shape checks.
py::array checked_float_array(const py::handle& object, const std::string& name, int ndim,
                              const std::string& shape) {
  const py::array array = array_argument(object, name, "a float32 or float64 numpy array");
  const char kind = array.dtype().kind();
  if (kind != 'f' || (array.itemsize() != 4 && array.itemsize() != 8)) {
    throw py::type_error(name + ": expected a float32 or float64 array, got dtype " +
                         std::string(py::str(array.dtype())));
  }
  require_shape(array, name, ndim, shape);
  return array;
}

/// Copies the float32 or float64 `array` into `out` (resized), refusing a non-finite entry.
template <class Out>
void copy_checked(const py::array& array, const std::string& name, Out& out) {
  const std::size_t count = static_cast<std::size_t>(array.size());
  out.resize(count);
  std::size_t bad = count;
  if (array.itemsize() == 4) {
    const auto source =
        py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
    const ReleasedGil free;
    bad = copy_finite(source.data(), count, out.data());
  } else {
    const auto source =
        py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
    const ReleasedGil free;
    bad = copy_finite(source.data(), count, out.data());
  }
  if (bad != count) {
    throw py::value_error(name + ": every entry must be finite; entry " + std::to_string(bad) +
                          " (flat index) is " +
                          (std::isnan(static_cast<double>(out[bad])) ? "nan" : "infinite"));
  }
}

std::vector<py::ssize_t> shape_of(const py::array& array) {
  std::vector<py::ssize_t> shape;
  for (py::ssize_t d = 0; d < array.ndim(); ++d) shape.push_back(array.shape(d));
  return shape;
}

}  // namespace

RealArray float_values(const py::handle& object, const std::string& name, int ndim,
                       const std::string& shape) {
  const py::array array = checked_float_array(object, name, ndim, shape);
  RealArray result;
  result.shape = shape_of(array);
  copy_checked(array, name, result.values);
  return result;
}

CostArray cost_array(const py::handle& object, const std::string& name, int ndim,
                     const std::string& shape) {
  const py::array array = checked_float_array(object, name, ndim, shape);
  CostArray result;
  result.shape = shape_of(array);
  result.single_precision = array.itemsize() == 4;
  if (result.single_precision) {
    copy_checked(array, name, result.floats);
  } else {
    copy_checked(array, name, result.doubles);
  }
  return result;
}

py::array_t<std::int64_t, py::array::c_style> integer_array(const py::handle& object,
                                                            const std::string& name, int ndim,
                                                            const std::string& shape) {
  const py::array array = array_argument(object, name, "an integer numpy array");
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u') {
    throw py::type_error(name + ": expected an integer array, got dtype " +
                         std::string(py::str(array.dtype())));
  }
  require_shape(array, name, ndim, shape);
  if (kind == 'u' && array.itemsize() == 8) {  // uint64 above int64's range would wrap
    const auto values =
        py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    for (py::ssize_t i = 0; i < values.size(); ++i) {
      if (values.data()[i] > static_cast<std::uint64_t>(INT64_MAX))
        throw py::value_error(name + ": entry " + std::to_string(i) + " is too large");
    }
  }
  return py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
}

Labeling labeling_from(const py::handle& object, const std::string& name, std::size_t num_variables,
                       int num_labels, const std::vector<py::ssize_t>& shape) {
  py::array array = array_argument(object, name, "an integer numpy array");
  std::string expected = "(" + std::to_string(num_variables) + ",)";
  bool fits = array.ndim() == 1 && static_cast<std::size_t>(array.shape(0)) == num_variables;
  if (!shape.empty() && shape.size() > 1) {
    expected += " or " + shape_text(shape);
    bool same = array.ndim() == static_cast<py::ssize_t>(shape.size());
    for (std::size_t d = 0; same && d < shape.size(); ++d) same = array.shape(d) == shape[d];
    fits = fits || same;
  }
  if (!fits) {
    throw py::value_error(name + ": expected a labeling of shape " + expected + ", got shape " +
                          shape_text(array));
  }
  const auto values = integer_array(array.reshape({array.size()}), name, 1, expected);
  Labeling labeling(num_variables);
  for (std::size_t v = 0; v < num_variables; ++v) {
    const std::int64_t label = values.data()[v];
    if (label < 0 || label >= num_labels) {
      throw py::value_error(name + ": labels must lie in [0, " + std::to_string(num_labels - 1) +
                            "]; variable " + std::to_string(v) + " has " + std::to_string(label));
    }
    labeling[v] = static_cast<Label>(label);
  }
  return labeling;
}

py::array_t<std::int32_t> labeling_array(const Labeling& labeling,
                                         const std::vector<py::ssize_t>& shape) {
  std::vector<py::ssize_t> dims =
      shape.empty() ? std::vector<py::ssize_t>{static_cast<py::ssize_t>(labeling.size())} : shape;
  py::array_t<std::int32_t> array(dims);
  std::copy(labeling.begin(), labeling.end(), array.mutable_data());
  return array;
}

}  // namespace c2f::python
