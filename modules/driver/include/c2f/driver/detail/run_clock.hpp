#pragma once
// The run clock of a coarse-to-fine run: wall time since the start, minus the time spent in
// the observer (which belongs to whoever watches, not to the method).

#include <chrono>

namespace c2f::detail {

class RunClock {
 public:
  using Clock = std::chrono::steady_clock;

  RunClock() : start_(Clock::now()) {}

  /// Seconds on the run clock.
  [[nodiscard]] double elapsed() const { return seconds(Clock::now() - start_) - excluded_; }

  /// Runs f() off the clock and returns its result.
  template <class F>
  auto off_the_clock(F&& f) {
    const auto begin = Clock::now();
    struct Exclude {
      RunClock* clock;
      Clock::time_point begin;
      ~Exclude() { clock->excluded_ += seconds(Clock::now() - begin); }
    } exclude{this, begin};
    return f();
  }

  [[nodiscard]] double excluded() const noexcept { return excluded_; }

 private:
  static double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

  Clock::time_point start_;
  double excluded_ = 0.0;
};

}  // namespace c2f::detail
