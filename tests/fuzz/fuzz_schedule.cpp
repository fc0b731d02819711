// Fuzz target: schedule text (the grammar, the stereo presets and the segmentation presets).
// Any text is refused with std::invalid_argument or parses to a schedule whose text parses
// again to the same text.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "c2f/vision/segmentation/segmentation_schedules.hpp"
#include "c2f/vision/stereo/stereo_schedules.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const c2f::Schedule schedule = c2f::vision::parse_stereo_schedule(text);
    (void)schedule.validate(85);
    const std::string printed = schedule.to_string();
    if (c2f::Schedule::parse(printed).to_string() != printed)
      throw std::logic_error("schedule text does not round-trip: " + printed);
  } catch (const std::invalid_argument&) {
  }
  try {
    (void)c2f::vision::parse_segmentation_schedule(text, 1 + static_cast<int>(size % 9));
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
