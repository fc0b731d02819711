#include "run_record.hpp"

#include <functional>
#include <stdexcept>
#include <utility>

#include "c2f/core/output_file.hpp"
#include "progress_printer.hpp"

namespace c2f::examples {

RunRecord::RunRecord(const std::filesystem::path& folder, std::vector<std::string> owned,
                     const std::string& trace_path, std::string tool, bool quiet)
    : output_(folder, std::move(owned)),
      trace_name_("the trace '" + trace_path + "'"),
      trace_file_(open_trace_file(output_.stage(trace_path).string())),
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
