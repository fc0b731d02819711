#pragma once
// What the anytime benchmarks read off a run: its (time, energy, error) after every step, the
// error shown at a deadline, and medians.

#include <algorithm>
#include <cmath>
#include <vector>

namespace c2f::bench {

struct TracePoint {
  double time, energy, error;
};

/// The error of the latest step at or before time t (the first point's before it).
inline double error_at(const std::vector<TracePoint>& trace, double t) {
  double error = trace.front().error;
  for (const TracePoint& p : trace) {
    if (p.time > t) break;
    error = p.error;
  }
  return error;
}

/// The median of the values that are not NaN (NaN when none).
inline double median(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }),
               values.end());
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

}  // namespace c2f::bench
