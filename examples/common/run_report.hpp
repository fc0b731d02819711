#pragma once
// What every tool reports about a finished run, written once: the run's part of summary.txt
// (levels, solver summary, observer time, an interrupt) and its last lines on stderr.

#include <ostream>
#include <span>
#include <string>

#include "c2f/driver/summary.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "interrupt_watch.hpp"

namespace c2f::examples {

/// Writes one line per level's partition, summary.report(), the observer's time off the run
/// clock and, after an interrupt, which signal ended the run and that the labeling is the best
/// found so far.
void write_run_report(std::ostream& out, std::span<const LevelReport> levels,
                      const Summary& summary, const InterruptWatch& interrupts);

/// On stderr: "TOOL: interrupted by SIG..." after an interrupt, and unless `quiet` the final
/// energy, steps, time, the reason the run ended and the output folder.
void print_run_end(const std::string& tool, const Summary& summary,
                   const InterruptWatch& interrupts, const std::string& out_dir, bool quiet);

}  // namespace c2f::examples
