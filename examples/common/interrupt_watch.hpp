#pragma once
// Ctrl-C for anytime runs: SIGINT and SIGTERM end a run at its next step instead of killing the
// process, so the best labeling so far can still be written.

#include <string>

#include "c2f/driver/observer.hpp"

namespace c2f::examples {

/// While alive, catches SIGINT and SIGTERM: the first one is recorded (signal(), observer()
/// then stops the run at its next step), a second one ends the process the usual way. The
/// previous handlers come back on destruction. At most one may be alive at a time
/// (std::logic_error otherwise).
class InterruptWatch {
 public:
  InterruptWatch();
  ~InterruptWatch();
  InterruptWatch(const InterruptWatch&) = delete;
  InterruptWatch& operator=(const InterruptWatch&) = delete;

  /// The signal received (SIGINT or SIGTERM), or 0.
  [[nodiscard]] int signal() const noexcept;
  [[nodiscard]] bool interrupted() const noexcept { return signal() != 0; }
  /// "SIGINT" or "SIGTERM" (empty when not interrupted).
  [[nodiscard]] std::string signal_name() const;
  /// The exit code shells use for a process ended by the signal: 128 + its number (130 for
  /// SIGINT, 143 for SIGTERM); 0 when not interrupted.
  [[nodiscard]] int exit_code() const noexcept;
  /// An observer that asks the run to stop once a signal has arrived.
  [[nodiscard]] Observer observer() const;
};

}  // namespace c2f::examples
