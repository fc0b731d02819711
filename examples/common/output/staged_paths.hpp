#pragma once
// Messages name the files a user asked for, not the hidden places they are staged in: a write
// that fails in a staging folder is reported under the path it was going to.

#include <string>

namespace c2f::examples {

/// Records that files written under `staging` are going to `target` (both folder or file
/// paths as the writers spell them). Entries stay for the life of the process, so messages
/// printed after the staging is gone still translate.
void note_staged_path(const std::string& staging, const std::string& target);

/// `message` with every recorded staging path replaced by its target.
std::string with_target_paths(std::string message);

}  // namespace c2f::examples
