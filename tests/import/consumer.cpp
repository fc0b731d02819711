// A coarse-to-fine solve of the synthetic problem with expansion and a schedule, built twice
// from this one file: with `import c2f;` only (C2F_IMPORT_MODULE; no c2f header), and with
// `#include "c2f/c2f.hpp"`. Prints the final energy and a checksum of the labeling, which the
// test import.same_result_as_headers compares between the two builds.

#include <cstdint>
#include <cstdio>
#include <functional>

#ifdef C2F_IMPORT_MODULE
import c2f;
#else
#include "c2f/c2f.hpp"
#endif

int main() {
  c2f::vision::SyntheticSpec spec;
  spec.shape = {96, 72};
  spec.num_labels = 8;
  spec.seed = 11;
  const c2f::vision::SyntheticProblem problem = c2f::vision::make_synthetic_problem(spec);
  c2f::ScheduleProvider levels(c2f::Schedule::parse("cp:1,1 cp:2,1 flat"), spec.shape);
  c2f::ExpansionSolver<> solver;
  c2f::Options options;
  options.plateau_steps = {4};  // the original problem: until expansion has converged
  long steps = 0;
  const c2f::Summary summary =
      c2f::coarse_to_fine(problem.energy, levels, solver, options, [&](const c2f::StepEvent&) {
        ++steps;
        return c2f::ObserverDecision::continue_run;
      });
  std::uint64_t checksum = 1469598103934665603ULL;
  for (const c2f::Label label : summary.labeling)
    checksum = (checksum ^ static_cast<std::uint64_t>(label)) * 1099511628211ULL;
  std::printf("energy %.17g steps %ld levels %zu labeling %016llx\n", summary.energy, steps,
              levels.reports().size(), static_cast<unsigned long long>(checksum));
  return steps > 0 ? 0 : 1;
}
