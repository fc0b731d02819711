#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "c2f/core/default_init_allocator.hpp"
#include "c2f/core/huge_page_allocator.hpp"

using namespace c2f;

namespace {

bool aligned_to_huge_page(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) % kHugePageBytes == 0;
}

/// The system's transparent huge page mode ("always", "madvise", "never"), or nothing where the
/// kernel does not say.
std::optional<std::string> thp_mode() {
  std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  if (!std::getline(file, line)) return std::nullopt;
  const auto open = line.find('['), close = line.find(']');
  if (open == std::string::npos || close == std::string::npos) return std::nullopt;
  return line.substr(open + 1, close - open - 1);
}

/// The THPeligible field of the mapping of this process holding `p` (/proc/self/smaps), or
/// nothing where the kernel does not report it.
std::optional<int> thp_eligible(const void* p) {
  std::ifstream smaps("/proc/self/smaps");
  const auto address = reinterpret_cast<std::uintptr_t>(p);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    const auto dash = line.find('-');
    const auto space = line.find(' ');
    if (dash != std::string::npos && space != std::string::npos && dash < space &&
        line.find(':') > space) {  // a mapping's header: "begin-end perms ..."
      const std::uintptr_t begin = std::stoull(line.substr(0, dash), nullptr, 16);
      const std::uintptr_t end = std::stoull(line.substr(dash + 1, space - dash - 1), nullptr, 16);
      inside = begin <= address && address < end;
    } else if (inside && line.rfind("THPeligible:", 0) == 0) {
      return std::stoi(line.substr(12));
    }
  }
  return std::nullopt;
}

}  // namespace

TEST_CASE("huge page allocator: small blocks as std::allocator's, large ones on 2 MiB",
          "[core][memory]") {
  LargeVector<double> small(100);
  std::iota(small.begin(), small.end(), 0.0);
  CHECK(small[99] == 99.0);

  const std::size_t large_count = kHugePageMinBytes / sizeof(double) + 1;
  LargeVector<double> large(large_count, 1.5);
  CHECK(aligned_to_huge_page(large.data()));
  CHECK(large.back() == 1.5);

  // Growing from a small block to a large one keeps every value.
  LargeVector<std::uint32_t> grown;
  for (std::uint32_t i = 0; i < 3 * (kHugePageMinBytes / sizeof(std::uint32_t)); ++i)
    grown.push_back(i);
  CHECK(aligned_to_huge_page(grown.data()));
  bool in_order = true;
  for (std::size_t i = 0; i < grown.size(); ++i) in_order = in_order && grown[i] == i;
  CHECK(in_order);

  // Copies, moves and swaps between vectors of the allocator (every instance equal).
  LargeVector<double> copy = large;
  CHECK(copy == large);
  LargeVector<double> moved = std::move(copy);
  CHECK(moved.size() == large_count);
  moved.swap(small);
  CHECK(small.size() == large_count);
  CHECK(moved.size() == 100);
  CHECK(HugePageAllocator<double>() == HugePageAllocator<int>());

  // DefaultInitVector's large blocks take the same path.
  DefaultInitVector<float> unwritten(kHugePageMinBytes / sizeof(float));
  CHECK(aligned_to_huge_page(unwritten.data()));
}

TEST_CASE("huge page allocator: a large block is advised for huge pages", "[core][memory]") {
  const std::optional<std::string> mode = thp_mode();
  if (!mode || (*mode != "always" && *mode != "madvise")) {
    WARN("no transparent huge pages on this system (mode: " << mode.value_or("unknown")
                                                            << "): the advice is not checked");
    return;
  }
  LargeVector<double> large(2 * kHugePageMinBytes / sizeof(double), 0.0);
  const std::optional<int> eligible = thp_eligible(large.data());
  if (!eligible) {
    WARN("this kernel reports no THPeligible in /proc/self/smaps: the advice is not checked");
    return;
  }
  CHECK(*eligible == 1);
}
