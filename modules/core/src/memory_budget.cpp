#include "c2f/core/memory_budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "c2f/support/memory_need.hpp"

namespace c2f {

namespace {

constexpr double kGib = 1024.0 * 1024.0 * 1024.0;

std::optional<std::size_t> physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return std::nullopt;
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page_size);
}

}  // namespace

std::size_t MemoryBudget::ceiling() const noexcept {
  return std::max(bytes, growth_limit);
}

std::size_t MemoryBudget::for_need(std::size_t need) const noexcept {
  return std::max(bytes, std::min(need, ceiling()));
}

std::string MemoryBudget::describe() const {
  std::string text = origin;
  if (ceiling() > bytes) {
    text += (text.empty() ? "" : "; ") + std::string("a run that needs more may take up to ") +
            format_bytes(static_cast<double>(ceiling()));
  }
  return format_bytes(static_cast<double>(bytes)) + (text.empty() ? "" : " (" + text + ")");
}

void MemoryBudget::require_within(const std::string& what, std::optional<std::size_t> need) const {
  if (need && *need <= ceiling()) return;
  const std::string text =
      need ? format_bytes(static_cast<double>(*need)) : std::string("more than 16 EiB");
  throw std::invalid_argument(what + " needs " + text + ", more than the run's memory budget of " +
                              describe());
}

void MemoryBudget::require(const std::string& what, std::optional<std::size_t> need) const {
  require_within(what, need);
  require_memory(what, need);
}

MemoryBudget default_memory_budget() {
  const std::optional<std::size_t> physical = physical_memory_bytes();
  const std::optional<std::size_t> available = available_memory_bytes();
  if (!physical && !available) return {std::size_t{4} << 30, "this machine's memory is unknown"};
  if (!physical) return {*available / 4, "a quarter of the memory available", *available / 2};
  const std::size_t quarter = *physical / 4, half = *physical / 2;
  const std::string share =
      "a quarter of this machine's " + format_bytes(static_cast<double>(*physical));
  if (available && *available < quarter) return {*available, "all that is available"};
  if (available && *available < half) return {quarter, share, *available};
  return {quarter, share, half};
}

MemoryBudget memory_budget_of_gib(double gib, const std::string& origin) {
  if (!std::isfinite(gib) || !(gib > 0.0) || gib * kGib >= 1.8e19) {
    throw std::invalid_argument(origin + ": the memory budget must be a finite number of GiB > 0");
  }
  return {static_cast<std::size_t>(gib * kGib), origin};
}

std::size_t energy_memory_bytes(const PairwiseEnergy& energy) {
  std::size_t bytes = energy.unaries().bytes() + energy.edges().size() * sizeof(Edge);
  for (const PairwiseTerm& term : energy.terms())
    bytes += sizeof(PairwiseTerm) + term.table_costs().size() * sizeof(double);
  return bytes;
}

ProblemSize problem_size(const PairwiseEnergy& energy) {
  return {energy.num_variables(), energy.num_labels(), energy.edges().size(),
          energy_memory_bytes(energy)};
}

}  // namespace c2f
