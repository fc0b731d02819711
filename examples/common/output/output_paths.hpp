#pragma once
// Every output path a run will write, checked against its inputs and against each other before
// anything is read, so no output lands over an input or over another output.

#include <string>
#include <vector>

namespace c2f::examples {

/// A path given on the command line, with the name a message uses for it ("--trace", "LEFT").
struct NamedPath {
  std::string what;
  std::string path;               ///< empty: not given (skipped)
  std::string default_name = {};  ///< an output's own default name in out_dir ("trace.csv")
};

/// What a run writes: into `out_dir` the files named by `owned` (patterns with one '*', as
/// OutputFolder takes them: name_matches), and the outputs the user named (`named`, e.g. --trace,
/// --export-uai), which may lie anywhere.
struct OutputPlan {
  std::string out_dir;
  std::vector<std::string> owned;
  std::vector<NamedPath> named;
};

/// Throws std::invalid_argument naming the path when a named output outside out_dir is a folder
/// or a socket, and naming both paths when a named output is the same file as an input (after
/// resolving symlinks; by device and inode where both exist), when two named outputs are one file,
/// when a named output in out_dir takes the name of a file the run writes there itself (other than
/// its own default_name), and when an input lies in out_dir under a name the run writes there.
/// Devices and pipes given as outputs are written in place and may be shared (whether a FIFO has a
/// reader is checked as it is opened: StagedFile).
void check_output_paths(const OutputPlan& plan, const std::vector<NamedPath>& inputs);

}  // namespace c2f::examples
