#pragma once
// What a command-line run leaves behind, as one object: its staged output folder, the trace it
// writes step by step, and the observers every tool attaches (trace, progress, interrupts).

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "c2f/driver/observer.hpp"
#include "c2f/driver/trace.hpp"
#include "interrupt_watch.hpp"
#include "output_folder.hpp"

namespace c2f::examples {

/// output.stage(target), with a refusal's message beginning with the flag that named the target.
std::filesystem::path staged_output(OutputFolder& output, const std::filesystem::path& target,
                                    const std::string& flag);

class RunRecord {
 public:
  /// Opens the output folder (OutputFolder with the files the tool owns) and the trace, staged
  /// like every output. Throws std::runtime_error naming the folder or the trace.
  RunRecord(const std::filesystem::path& folder, std::vector<std::string> owned,
            const std::string& trace_path, std::string tool, bool quiet);

  /// Where the run's other outputs are written before commit().
  [[nodiscard]] const std::filesystem::path& staging() const noexcept { return output_.staging(); }

  /// Where to write an output the user named (OutputFolder::stage): in the staging folder when
  /// it lies in the output folder, beside its target until commit() otherwise.
  /// A refusal's message begins with `flag`.
  std::filesystem::path stage(const std::filesystem::path& target, const std::string& flag) {
    return staged_output(output_, target, flag);
  }

  /// The run's observer: a trace row per step (with an error column when `error` is given),
  /// progress on stderr unless quiet, `extra` observers, and a stop once `interrupts` caught a
  /// signal. Call once, before the run.
  Observer observer(TraceWriter::ErrorFunction error, const InterruptWatch& interrupts,
                    std::vector<Observer> extra = {});

  /// The tool's name, as its messages begin.
  [[nodiscard]] const std::string& tool() const noexcept { return tool_; }

  /// Closes the trace (a failed write is an error naming it) and moves every output into place.
  void commit();

 private:
  OutputFolder output_;
  std::string trace_name_;
  std::ofstream trace_file_;
  std::optional<TraceWriter> trace_;
  std::string tool_;
  bool quiet_;
};

}  // namespace c2f::examples
