// c2f-synthetic: solves a synthetic labeling problem (piecewise-constant image under noise)
// flat and coarse to fine with the same solver and clock, and prints both traces. The options
// become library calls in named steps: make the problem, solve flat, solve coarse to fine,
// report, write.

#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

#include "c2f/c2f.hpp"
#include "synthetic_options.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {

/// One ICM run over `levels`; prints its trace and summary, and writes the trace to
/// `trace_path` unless that is empty.
template <class Provider>
Summary solve(const char* name, const SyntheticProblem& problem, Provider& levels,
              const Options& options, const std::string& trace_path) {
  std::ostringstream trace;
  TraceWriter writer(
      trace, [&](std::span<const Label> ground) { return pixel_error(ground, problem.truth); });
  IcmSolver solver;
  Summary summary = coarse_to_fine(problem.energy, levels, solver, options, std::ref(writer));
  std::cout << "# trace: " << name << "\n"
            << trace.str() << "# summary: " << name << "\n"
            << summary.report() << "\n";
  if (!trace_path.empty()) {
    std::ofstream file = open_trace_file(trace_path);
    file << trace.str();
  }
  return summary;
}

void report(const char* name, const Summary& summary, const SyntheticProblem& problem) {
  std::cout << name << " energy " << summary.energy << ", error "
            << pixel_error(summary.labeling, problem.truth) << ", " << summary.seconds << " s\n";
}

void write_pictures(const std::string& out_dir, const SyntheticProblem& problem,
                    const vision::SyntheticSpec& spec, const Summary& flat, const Summary& c2f) {
  const std::filesystem::path out(out_dir);
  write_label_pgm((out / "truth.pgm").string(), problem.truth, spec.shape, spec.num_labels);
  write_label_pgm((out / "flat.pgm").string(), flat.labeling, spec.shape, spec.num_labels);
  write_label_pgm((out / "c2f.pgm").string(), c2f.labeling, spec.shape, spec.num_labels);
  std::cerr << "c2f-synthetic: wrote traces and images to " << out_dir << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const auto parsed = examples::parse_synthetic_command(argc, argv);
    if (!parsed) return 0;
    const examples::SyntheticCommand& command = *parsed;
    const bool files = !command.out_dir.empty();
    if (files) std::filesystem::create_directories(command.out_dir);
    const auto path = [&](const char* name) {
      return files ? (std::filesystem::path(command.out_dir) / name).string() : std::string();
    };

    BlockHierarchy hierarchy(command.spec.shape, command.block_sizes);  // checks the sizes first
    const SyntheticProblem problem = make_synthetic_problem(command.spec);
    std::cerr << "c2f-synthetic: " << command.spec.shape.width << "x" << command.spec.shape.height
              << " pixels, " << command.spec.num_labels << " labels, "
              << problem.energy.edges().size() << " edges\n";

    PartitionList flat_levels;
    const Summary flat =
        solve("flat", problem, flat_levels, command.options, path("trace-flat.csv"));
    const Summary c2f = solve("c2f", problem, hierarchy, command.options, path("trace-c2f.csv"));

    report("flat:", flat, problem);
    report("c2f: ", c2f, problem);
    if (files) write_pictures(command.out_dir, problem, command.spec, flat, c2f);
  } catch (const std::exception& error) {
    std::cerr << "c2f-synthetic: error: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
