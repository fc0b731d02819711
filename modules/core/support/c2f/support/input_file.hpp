#pragma once
// The input layer: every file the library or a tool reads is checked here before it is read.
// A path is examined without throwing (a name too long for the system, a loop of links or a
// folder without permission gives a reason, not a std::filesystem::filesystem_error from deep
// inside a loader), opened so that it cannot block (a FIFO without a writer, a device), and read
// only when it is a regular file of bounded size (a link to /dev/zero is refused, not read until
// memory runs out).

#include <cstddef>
#include <string>
#include <string_view>

namespace c2f {

/// Empty when `path` names a regular file (after following links); otherwise why it cannot be
/// read as one: "does not exist", "is a folder, not a file", "is not a regular file (a FIFO)"
/// (or a device, a socket) or "cannot be examined (<system message>)".
std::string why_not_a_file(const std::string& path);

/// The whole content of the file `path`, read as the input layer promises: the file is opened
/// without blocking and read only when it is a regular file of at most `max_bytes` bytes.
/// Throws std::invalid_argument "<what> '<path>' <why>" otherwise ("is not a regular file (a
/// FIFO)", "is 3.2 GiB; a <what> of at most 64.0 MiB is expected"), and std::runtime_error
/// naming it when reading fails.
std::string read_input_file(const std::string& path, std::string_view what, std::size_t max_bytes);

/// The most memory reading one input may take (a decoded image by its header's size, a PFM, a
/// UAI model's declared costs): the run's memory budget. The tools set it from --memory before
/// they read anything; until it is set, the machine's default budget's ceiling
/// (default_memory_budget). Process-wide, read by every loader.
void set_input_memory_limit(std::size_t bytes) noexcept;
[[nodiscard]] std::size_t input_memory_limit();

/// Throws std::invalid_argument "<what> '<path>' needs <bytes> <how>, more than the <limit> the
/// run's memory budget allows for one input" when `bytes` exceeds input_memory_limit().
void require_input_memory(const std::string& path, std::string_view what, double bytes,
                          std::string_view how);

/// The size bound for small text inputs people write by hand or tools write as tables
/// (calib.txt, scene tables, bench rows, traces): 64 MiB.
inline constexpr std::size_t kMaxTextInputBytes = std::size_t{64} << 20;

}  // namespace c2f
