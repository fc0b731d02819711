#include "c2f/driver/summary.hpp"

#include "c2f/support/number_text.hpp"

namespace c2f {

std::string Summary::report() const {
  std::string text;
  for (const LevelSummary& level : levels) {
    if (level.skipped) {
      text += c_format(
          "level %d: %zu groups, skipped (does not fit: Options::coarse_level_fits), "
          "partition %.3fs\n",
          level.level, level.num_variables, level.partition_seconds);
      continue;
    }
    text += c_format(
        "level %d: %zu variables, %ld steps, energy %.6f -> %.6f, partition %.3fs, "
        "setup %.3fs, solve %.3fs\n",
        level.level, level.num_variables, level.steps, level.start_energy, level.final_energy,
        level.partition_seconds, level.setup_seconds, level.solve_seconds);
  }
  text += c_format("final energy %.6f after %ld steps in %.3fs (%s)\n", energy, total_steps,
                   seconds, std::string(to_string(reason)).c_str());
  return text;
}

}  // namespace c2f
