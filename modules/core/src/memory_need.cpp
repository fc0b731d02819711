#include "c2f/support/memory_need.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include "c2f/support/number_text.hpp"

namespace c2f {

std::optional<std::size_t> checked_product(std::initializer_list<std::size_t> factors) {
  std::size_t product = 1;
  for (const std::size_t factor : factors) {
    if (factor != 0 && product > std::numeric_limits<std::size_t>::max() / factor)
      return std::nullopt;
    product *= factor;
  }
  return product;
}

std::optional<std::size_t> checked_sum(std::initializer_list<std::size_t> terms) {
  std::size_t sum = 0;
  for (const std::size_t term : terms) {
    if (sum > std::numeric_limits<std::size_t>::max() - term) return std::nullopt;
    sum += term;
  }
  return sum;
}

namespace {

/// MemAvailable from /proc/meminfo, in bytes.
std::optional<std::size_t> meminfo_available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::size_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit) {
    if (key == "MemAvailable:") return kib * 1024;
  }
  return std::nullopt;
}

std::optional<std::size_t> physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return std::nullopt;
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page_size);
}

}  // namespace

std::optional<std::size_t> available_memory_bytes() {
  std::optional<std::size_t> available = meminfo_available();
  if (!available) available = physical_memory();
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const auto cap = static_cast<std::size_t>(limit.rlim_cur);
    available = available ? std::min(*available, cap) : cap;
  }
  return available;
}

std::string format_bytes(double bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6) {
    bytes /= 1024.0;
    ++unit;
  }
  return unit == 0 ? c_format("%.0f %s", bytes, units[unit])
                   : c_format("%.1f %s", bytes, units[unit]);
}

void require_memory(const std::string& what, std::optional<std::size_t> bytes) {
  const std::optional<std::size_t> available = available_memory_bytes();
  if (!available) return;
  if (bytes && *bytes <= *available) return;
  const std::string need = bytes ? format_bytes(static_cast<double>(*bytes)) : "more than 16 EiB";
  throw std::invalid_argument(what + " needs " + need + ", more than the " +
                              format_bytes(static_cast<double>(*available)) +
                              " this machine has available");
}

}  // namespace c2f
