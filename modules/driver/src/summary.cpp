#include "c2f/driver/summary.hpp"

#include <cstdio>

namespace c2f {

std::string Summary::report() const {
  std::string text;
  char line[256];
  for (const LevelSummary& level : levels) {
    if (level.skipped) {
      std::snprintf(line, sizeof line,
                    "level %d: %zu groups, skipped (does not fit: Options::coarse_level_fits), "
                    "partition %.3fs\n",
                    level.level, level.num_variables, level.partition_seconds);
      text += line;
      continue;
    }
    std::snprintf(line, sizeof line,
                  "level %d: %zu variables, %ld steps, energy %.6f -> %.6f, partition %.3fs, "
                  "setup %.3fs, solve %.3fs\n",
                  level.level, level.num_variables, level.steps, level.start_energy,
                  level.final_energy, level.partition_seconds, level.setup_seconds,
                  level.solve_seconds);
    text += line;
  }
  std::snprintf(line, sizeof line, "final energy %.6f after %ld steps in %.3fs (%s)\n", energy,
                total_steps, seconds, std::string(to_string(reason)).c_str());
  text += line;
  return text;
}

}  // namespace c2f
