#include "c2f/support/output_file.hpp"

#include <stdexcept>

namespace c2f {

void close_checked(std::ofstream& stream, const std::string& what) {
  stream.flush();
  const bool flushed = stream.good();
  stream.close();
  if (!flushed || stream.fail()) throw std::runtime_error("writing " + what + " failed");
}

}  // namespace c2f
