#include "c2f/driver/trace.hpp"

#include <stdexcept>

#include "c2f/support/number_text.hpp"

namespace c2f {

namespace {

/// The header line of a trace (without newline).
std::string trace_header(bool with_error) {
  return with_error ? "time_s,level,step,energy,num_vars,error"
                    : "time_s,level,step,energy,num_vars";
}

}  // namespace

TraceWriter::TraceWriter(std::ostream& out, ErrorFunction error, std::string name)
    : out_(&out), error_(std::move(error)), name_(std::move(name)) {
  *out_ << trace_header(static_cast<bool>(error_)) << '\n';
}

ObserverDecision TraceWriter::operator()(const StepEvent& event) {
  *out_ << c_format("%.6f,%d,%ld,%.17g,%zu", event.time_s, event.level, event.step, event.energy,
                    event.num_variables);
  if (error_) {
    *out_ << c_format(",%.9g", error_(event.ground_labeling(ground_)));
  }
  *out_ << '\n';
  if (!*out_) throw std::runtime_error("writing a row of " + name_ + " failed");
  return ObserverDecision::continue_run;
}

std::ofstream open_trace_file(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("trace: cannot open '" + path + "' for writing");
  return out;
}

}  // namespace c2f
