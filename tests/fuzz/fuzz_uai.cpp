// Fuzz target: the UAI reader. Any input is either refused with std::invalid_argument or read
// into an energy that writes and reads back with the same variables, labels and edges (when
// its costs are within write_uai's range).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "c2f/core/uai.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::optional<c2f::PairwiseEnergy> read;
  try {
    read.emplace(c2f::read_uai(in, "fuzz.uai"));
  } catch (const std::invalid_argument&) {
    return 0;
  }
  const c2f::PairwiseEnergy& energy = *read;
  std::ostringstream out;
  try {
    c2f::write_uai(energy, out);
  } catch (const std::invalid_argument&) {
    return 0;  // costs of one factor too far apart for potentials
  }
  std::istringstream again(out.str());
  const c2f::PairwiseEnergy back = c2f::read_uai(again, "round-trip.uai");
  if (back.num_variables() != energy.num_variables() || back.num_labels() != energy.num_labels() ||
      back.edges().size() != energy.edges().size())
    throw std::logic_error("UAI round trip changed the model's shape");
  return 0;
}
