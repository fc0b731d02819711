#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>

#include "c2f/adapters/icm/icm.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/driver/trace.hpp"
#include "c2f/lift/block_hierarchy.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

TEST_CASE("trace rows follow the documented CSV format", "[core][trace]") {
  Rng rng(2);
  const PairwiseEnergy energy = random_grid_energy(rng, 8, 8, 3);
  BlockHierarchy levels(GridShape{8, 8}, {4});
  IcmSolver solver;
  std::ostringstream plain, with_error;
  TraceWriter writer(plain);
  TraceWriter error_writer(
      with_error, [](std::span<const Label> ground) { return static_cast<double>(ground.size()); });
  const Summary summary = coarse_to_fine(energy, levels, solver, Options{},
                                         observe_all({std::ref(writer), std::ref(error_writer)}));
  std::istringstream lines(plain.str());
  std::string line;
  std::getline(lines, line);
  CHECK(line == "time_s,level,step,energy,num_vars");
  long rows = 0;
  while (std::getline(lines, line)) {
    ++rows;
    CHECK(std::count(line.begin(), line.end(), ',') == 4);
  }
  CHECK(rows ==
        summary.total_steps + static_cast<long>(summary.levels.size()));  // + step 0 of each level
  std::istringstream error_lines(with_error.str());
  std::getline(error_lines, line);
  CHECK(line == "time_s,level,step,energy,num_vars,error");
  std::getline(error_lines, line);
  CHECK(line.substr(line.rfind(',') + 1) == "64");  // error column = ground labeling size
  CHECK_THROWS_WITH(open_trace_file("/nonexistent-dir/trace.csv"),
                    Catch::Contains("/nonexistent-dir/trace.csv"));
}
