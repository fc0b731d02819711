#pragma once
// Whether a path names a file that can be read, asked without throwing: a name too long for the
// system, a loop of links or a folder without permission gives a reason, not a
// std::filesystem::filesystem_error from deep inside a loader.

#include <string>

namespace c2f {

/// Empty when `path` names a regular file (after following links); otherwise why it cannot be
/// read as one: "does not exist", "is a folder, not a file", "is not a regular file" or
/// "cannot be examined (<system message>)".
std::string why_not_a_file(const std::string& path);

}  // namespace c2f
