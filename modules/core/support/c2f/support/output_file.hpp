#pragma once
// Writing a file so that a failed write is an error, never a silent success.

#include <fstream>
#include <stdexcept>
#include <string>

namespace c2f {

/// Flushes and closes a written file stream; throws std::runtime_error naming `what` when any
/// write failed (a full disk, /dev/full) so that a failed write is never a silent success.
void close_checked(std::ofstream& stream, const std::string& what);

}  // namespace c2f
