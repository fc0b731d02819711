#pragma once
// Progress of a run on stderr, for the command-line tools.

#include <chrono>
#include <string>

#include "c2f/driver/observer.hpp"

namespace c2f::examples {

/// An observer that prints "<tool>: level L (lifted|original, N variables) step S energy E at
/// T s" to stderr at every level start and then at most every `interval_seconds`; prints
/// nothing when quiet. Never stops the run.
class ProgressPrinter {
 public:
  ProgressPrinter(std::string tool, bool quiet, double interval_seconds = 2.0);
  ObserverDecision operator()(const StepEvent& event);

 private:
  std::string tool_;
  bool quiet_;
  std::chrono::steady_clock::duration interval_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace c2f::examples
