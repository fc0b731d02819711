#include "folder_swap.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>

namespace c2f::examples {

namespace fs = std::filesystem;

namespace {

bool carriable(fs::file_type type) {
  return type == fs::file_type::regular || type == fs::file_type::symlink ||
         type == fs::file_type::directory;
}

[[noreturn]] void cannot_carry(const fs::path& entry, const std::string& why) {
  throw std::runtime_error("cannot keep '" + entry.string() +
                           "' in the new version of its folder: " + why);
}

void carry_entry(const fs::path& from, const fs::path& to) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(from, error);
  switch (status.type()) {
    case fs::file_type::regular:
      fs::create_hard_link(from, to, error);
      if (error) {
        error.clear();
        fs::copy_file(from, to, fs::copy_options::overwrite_existing, error);
      }
      break;
    case fs::file_type::symlink:
      fs::copy_symlink(from, to, error);
      break;
    case fs::file_type::directory:
      // Filled first, then given the old folder's permissions (a folder without write
      // permission could not be filled, nor removed again should the run fail).
      fs::create_directory(to, error);
      for (const auto& entry : fs::directory_iterator(from, error)) {
        carry_entry(entry.path(), to / entry.path().filename());
      }
      if (!error) fs::permissions(to, status.permissions(), error);
      break;
    default:
      cannot_carry(from, "it is not a file, folder or symbolic link");
  }
  if (error) cannot_carry(from, error.message());
}

}  // namespace

void check_carriable(const fs::path& folder, const KeepEntry& keep) {
  std::error_code error;
  for (auto entry = fs::recursive_directory_iterator(folder, error);
       entry != fs::recursive_directory_iterator(); entry.increment(error)) {
    const fs::path relative = entry->path().lexically_relative(folder);
    if (!keep(relative.begin()->string())) {
      entry.disable_recursion_pending();  // an entry the run replaces: nothing in it is kept
      continue;
    }
    const fs::file_type type = entry->symlink_status(error).type();
    if (!carriable(type)) {
      throw std::runtime_error("the output folder holds '" + entry->path().string() +
                               "', which is not a file, folder or symbolic link: a run "
                               "replaces the folder and cannot keep it; move it out");
    }
    if (type == fs::file_type::directory && ::access(entry->path().c_str(), R_OK | X_OK) != 0) {
      throw std::runtime_error("the output folder holds '" + entry->path().string() +
                               "', a folder this run cannot read (" + std::strerror(errno) +
                               "): a run replaces the folder and cannot keep it; make it "
                               "readable, or move it out");
    }
  }
}

void carry_over(const fs::path& folder, const fs::path& staging, const KeepEntry& keep) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    std::error_code absent;
    if (!keep(name) || fs::exists(fs::symlink_status(staging / name, absent))) continue;
    carry_entry(entry.path(), staging / name);
  }
  if (error) cannot_carry(folder, error.message());
  // The new version has the old one's permissions.
  const fs::perms perms = fs::status(folder, error).permissions();
  if (!error) fs::permissions(staging, perms, error);
}

void swap_in(const fs::path& staging, const fs::path& folder, const fs::path& retired) {
  if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, folder.c_str(), RENAME_EXCHANGE) == 0)
    return;
  const int why = errno;
  if (why != EINVAL && why != ENOSYS && why != ENOTSUP) {
    throw std::runtime_error("cannot put the new '" + folder.string() +
                             "' in place: " + std::strerror(why));
  }
  // The file system cannot exchange: two renames, the old version kept aside in between.
  std::error_code error;
  fs::rename(folder, retired, error);
  if (!error) fs::rename(staging, folder, error);
  if (error) {
    std::error_code ignored;
    restore_retired_folder(retired, folder);
    throw std::runtime_error("cannot put the new '" + folder.string() +
                             "' in place: " + error.message());
  }
  fs::rename(retired, staging, error);  // where the caller removes the old version
}

bool restore_retired_folder(const fs::path& retired, const fs::path& folder) {
  std::error_code error;
  if (fs::exists(fs::symlink_status(folder, error)) ||
      !fs::is_directory(fs::symlink_status(retired, error)))
    return false;
  fs::rename(retired, folder, error);
  return !error;
}

}  // namespace c2f::examples
