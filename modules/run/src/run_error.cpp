#include "c2f/run/run_error.hpp"

namespace c2f {

void RunConfigError::throw_if(const std::string& message) {
  if (message.empty()) return;
  const std::size_t colon = message.find(": ");
  if (colon == std::string::npos) throw RunConfigError("config", message);
  throw RunConfigError(message.substr(0, colon), message.substr(colon + 2));
}

}  // namespace c2f
