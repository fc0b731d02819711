#include "run_report.hpp"

#include <cstdio>

namespace c2f::examples {

void write_run_report(std::ostream& out, std::span<const LevelReport> levels,
                      const Summary& summary, const InterruptWatch& interrupts) {
  for (const LevelReport& level : levels) {
    out << "partition " << level.level << ": " << level.num_groups << " groups in " << level.seconds
        << " s on " << level.threads << (level.threads == 1 ? " thread\n" : " threads\n");
  }
  out << summary.report() << "observer (trace, progress): " << summary.observer_seconds
      << " s off the run clock\n";
  if (interrupts.interrupted()) {
    out << "interrupted by " << interrupts.signal_name() << " after " << summary.total_steps
        << " steps: the labeling written is the best found so far\n";
  }
}

void print_run_end(const std::string& tool, const Summary& summary,
                   const InterruptWatch& interrupts, const std::string& out_dir, bool quiet) {
  if (interrupts.interrupted()) {
    std::fprintf(stderr, "%s: interrupted by %s: wrote the best labeling found so far\n",
                 tool.c_str(), interrupts.signal_name().c_str());
  }
  if (quiet) return;
  std::fprintf(stderr, "%s: final energy %.6f after %ld steps in %.2f s (%s); wrote %s\n",
               tool.c_str(), summary.energy, summary.total_steps, summary.seconds,
               std::string(to_string(summary.reason)).c_str(), out_dir.c_str());
}

}  // namespace c2f::examples
