#include "numpy_input.hpp"

#include <cmath>

namespace c2f::python {

std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::string text = "(";
  for (std::size_t d = 0; d < shape.size(); ++d) text += (d ? ", " : "") + std::to_string(shape[d]);
  return text + (shape.size() == 1 ? ",)" : ")");
}

std::string shape_text(const py::array& array) {
  return shape_text(std::vector<py::ssize_t>(array.shape(), array.shape() + array.ndim()));
}

namespace {

py::array as_numpy(const py::handle& object, const std::string& name, const std::string& what) {
  if (py::isinstance<py::array>(object)) return py::reinterpret_borrow<py::array>(object);
  if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object)) {
    return py::array::ensure(object);
  }
  throw py::type_error(name + ": expected " + what + ", got " +
                       std::string(py::str(py::type::of(object).attr("__name__"))));
}

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

/// Converts and checks `count` entries; returns the index of the first non-finite one, or
/// `count`.
template <class T>
std::size_t convert_finite(const T* data, std::size_t count, double* out) {
  std::size_t bad = count;
  for (std::size_t i = 0; i < count; ++i) {
    const double value = static_cast<double>(data[i]);
    out[i] = value;
    if (!std::isfinite(value) && bad == count) bad = i;
  }
  return bad;
}

}  // namespace

FloatValues float_values(const py::handle& object, const std::string& name, int ndim,
                         const std::string& shape) {
  const py::array array = as_numpy(object, name, "a float32 or float64 numpy array");
  const char kind = array.dtype().kind();
  if (kind != 'f' || (array.itemsize() != 4 && array.itemsize() != 8)) {
    throw py::type_error(name + ": expected a float32 or float64 array, got dtype " +
                         std::string(py::str(array.dtype())));
  }
  require_shape(array, name, ndim, shape);
  FloatValues result;
  for (py::ssize_t d = 0; d < array.ndim(); ++d) result.shape.push_back(array.shape(d));
  const std::size_t count = static_cast<std::size_t>(array.size());
  result.values.resize(count);
  std::size_t bad = count;
  if (array.itemsize() == 4) {
    const auto source =
        py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
    py::gil_scoped_release free;
    bad = convert_finite(source.data(), count, result.values.data());
  } else {
    const auto source =
        py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
    py::gil_scoped_release free;
    bad = convert_finite(source.data(), count, result.values.data());
  }
  if (bad != count) {
    throw py::value_error(name + ": every entry must be finite; entry " + std::to_string(bad) +
                          " (flat index) is " +
                          (std::isnan(result.values[bad]) ? "nan" : "infinite"));
  }
  return result;
}

py::array_t<std::int64_t, py::array::c_style> integer_array(const py::handle& object,
                                                            const std::string& name, int ndim,
                                                            const std::string& shape) {
  const py::array array = as_numpy(object, name, "an integer numpy array");
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
  py::array array = as_numpy(object, name, "an integer numpy array");
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
