#pragma once
// Replacing a whole folder in one step: a new version is built beside it (with the entries of
// the old one that should stay), then the two are exchanged by one rename.

#include <filesystem>
#include <functional>
#include <string>

namespace c2f::examples {

/// Whether an entry of the old folder (its name) goes into the new version.
using KeepEntry = std::function<bool(const std::string& name)>;

/// Throws std::runtime_error naming the entry when `folder` holds an entry that `keep` keeps and
/// carry_over() could not carry (a FIFO, socket or device), so a run can refuse before it works.
void check_carriable(const std::filesystem::path& folder, const KeepEntry& keep);

/// Gives `staging` every entry of `folder` that `keep` keeps and that `staging` does not hold
/// already: regular files as hard links (copies where the file system refuses a link), symbolic
/// links as links, folders rebuilt entry by entry. The old folder is not changed. Throws
/// std::runtime_error naming the entry that cannot be carried.
void carry_over(const std::filesystem::path& folder, const std::filesystem::path& staging,
                const KeepEntry& keep);

/// Puts `staging` in the place of `folder` and leaves the old version at `staging`, by one
/// renameat2(RENAME_EXCHANGE), so any interruption leaves one version or the other in place.
/// Where the file system cannot exchange, `folder` is renamed to `retired` and `staging` to
/// `folder`; a process that dies between the two leaves no `folder`, which
/// restore_retired_folder() puts back. Throws std::runtime_error naming the folder.
void swap_in(const std::filesystem::path& staging, const std::filesystem::path& folder,
             const std::filesystem::path& retired);

/// After a fallback swap_in() that died half way: when `folder` is absent and `retired` is
/// present, renames `retired` back to `folder`. Returns whether it did.
bool restore_retired_folder(const std::filesystem::path& retired,
                            const std::filesystem::path& folder);

}  // namespace c2f::examples
