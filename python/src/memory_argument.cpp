#include "memory_argument.hpp"

#include <pybind11/pybind11.h>

#include <stdexcept>

#include "c2f/support/number_text.hpp"
#include "numpy_input.hpp"

namespace c2f::python {

namespace py = pybind11;

MemoryBudget memory_budget_from(const py::handle& argument) {
  if (argument.is_none()) return default_memory_budget();
  const char* const expected = "memory: expected a finite number of GiB > 0, or None (the default)";
  double gib = 0;
  try {
    gib = real_argument(argument, "memory");
  } catch (const py::value_error&) {
    throw py::value_error(expected);
  }
  if (gib <= 0) throw py::value_error(expected);
  return memory_budget_of_gib(gib, "memory=" + format_real(gib));
}

void require_memory_within(const MemoryBudget& budget, const std::string& what,
                           std::optional<std::size_t> bytes) {
  try {
    budget.require(what, bytes);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("memory: ") + error.what());
  }
}

}  // namespace c2f::python
