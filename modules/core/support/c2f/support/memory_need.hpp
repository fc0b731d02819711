#pragma once
// Sizes and memory checked before allocation: products that cannot wrap around, and a clear
// "needs N GiB" error instead of std::bad_alloc (or the out-of-memory killer) when a problem
// cannot fit.

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>

namespace c2f {

/// The product of `factors`, or std::nullopt when it does not fit in std::size_t.
std::optional<std::size_t> checked_product(std::initializer_list<std::size_t> factors);
/// The sum of `terms`, or std::nullopt when it does not fit in std::size_t.
std::optional<std::size_t> checked_sum(std::initializer_list<std::size_t> terms);

/// The bytes this process may still allocate: the smaller of the memory the kernel reports
/// available (MemAvailable in /proc/meminfo, else the physical memory) and the address-space
/// limit (RLIMIT_AS), when either is known; std::nullopt when neither is.
std::optional<std::size_t> available_memory_bytes();

/// "12.3 GiB", "512 MiB", "4 KiB": a byte count for messages.
std::string format_bytes(double bytes);

/// Throws std::invalid_argument "<what> needs <bytes>, more than the <available> this machine
/// has available" when `bytes` (std::nullopt: beyond std::size_t) exceeds
/// available_memory_bytes(). Does nothing when the available memory is unknown.
void require_memory(const std::string& what, std::optional<std::size_t> bytes);

}  // namespace c2f
