#pragma once
// CSV traces of anytime runs: `time_s,level,step,energy,num_vars[,error]`, one row per step.

#include <fstream>
#include <functional>
#include <ostream>
#include <span>
#include <string>

#include "c2f/driver/observer.hpp"

namespace c2f {

/// An observer that writes one CSV row per StepEvent to a stream. When an error function is
/// given, the trace has an `error` column holding error(ground labeling) for every row.
class TraceWriter {
 public:
  using ErrorFunction = std::function<double(std::span<const Label> ground_labeling)>;

  /// Writes the header immediately. The stream must outlive the writer. `name` names the
  /// trace in the error thrown when a write fails ("the trace 'run/trace.csv'").
  explicit TraceWriter(std::ostream& out, ErrorFunction error = {}, std::string name = "the trace");

  ObserverDecision operator()(const StepEvent& event);

 private:
  std::ostream* out_;
  ErrorFunction error_;
  std::string name_;
  Labeling ground_;  // a coarse level's ground labeling, its memory kept from row to row
};

/// Opens `path` for writing a trace; throws std::runtime_error naming the path on failure.
std::ofstream open_trace_file(const std::string& path);

}  // namespace c2f
