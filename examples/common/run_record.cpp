#include "run_record.hpp"

#include <functional>
#include <stdexcept>
#include <utility>

#include "c2f/support/output_file.hpp"
#include "progress_printer.hpp"

namespace c2f::examples {

std::filesystem::path staged_output(OutputFolder& output, const std::filesystem::path& target,
                                    const std::string& flag) {
  try {
    return output.stage(target);
  } catch (const std::invalid_argument& refused) {
    throw std::invalid_argument(flag + ": " + refused.what());
  }
}

RunRecord::RunRecord(const std::filesystem::path& folder, std::vector<std::string> owned,
                     const std::string& trace_path, std::string tool, bool quiet)
    : output_(folder, tool, std::move(owned)),
      trace_name_("the trace '" + trace_path + "'"),
      trace_file_(open_trace_file(staged_output(output_, trace_path, "--trace").string())),
      tool_(std::move(tool)),
      quiet_(quiet) {}

Observer RunRecord::observer(TraceWriter::ErrorFunction error, const InterruptWatch& interrupts,
                             std::vector<Observer> extra) {
  if (trace_) throw std::logic_error("RunRecord::observer: call it once per run");
  trace_.emplace(trace_file_, std::move(error), trace_name_);
  std::vector<Observer> observers{std::ref(*trace_), ProgressPrinter(tool_, quiet_)};
  for (Observer& o : extra) observers.push_back(std::move(o));
  observers.push_back(interrupts.observer());
  return observe_all(std::move(observers));
}

void RunRecord::commit() {
  close_checked(trace_file_, trace_name_);
  output_.commit();
}

}  // namespace c2f::examples
