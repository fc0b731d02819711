#include "progress_printer.hpp"

#include <cstdio>

namespace c2f::examples {

ProgressPrinter::ProgressPrinter(std::string tool, bool quiet, double interval_seconds)
    : tool_(std::move(tool)),
      quiet_(quiet),
      interval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(interval_seconds))),
      last_(std::chrono::steady_clock::now()) {}

ObserverDecision ProgressPrinter::operator()(const StepEvent& event) {
  if (quiet_) return ObserverDecision::continue_run;
  const auto now = std::chrono::steady_clock::now();
  if (event.step == 0 || now - last_ > interval_) {
    std::fprintf(stderr, "%s: level %d (%s, %zu variables) step %ld energy %.4f at %.2f s\n",
                 tool_.c_str(), event.level, event.at_original ? "original" : "lifted",
                 event.num_variables, event.step, event.energy, event.time_s);
    last_ = now;
  }
  return ObserverDecision::continue_run;
}

}  // namespace c2f::examples
