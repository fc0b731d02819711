#include "c2f/core/input_file.hpp"

#include <filesystem>
#include <system_error>

namespace c2f {

std::string why_not_a_file(const std::string& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) return "does not exist";
  if (error) return "cannot be examined (" + error.message() + ")";
  if (std::filesystem::is_regular_file(status)) return "";
  if (std::filesystem::is_directory(status)) return "is a folder, not a file";
  return "is not a regular file";
}

}  // namespace c2f
