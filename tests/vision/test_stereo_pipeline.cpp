// The whole stereo pipeline on a synthetic pair with known disparity, flat and coarse to fine.

#include <catch2/catch.hpp>

#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/lift/partition_list.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/vision/stereo/disparity_io.hpp"
#include "c2f/vision/stereo/evaluation.hpp"
#include "c2f/vision/stereo/stereo_schedules.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"
#include "c2f/vision/superpixels.hpp"
#include "support/synthetic_stereo.hpp"

using namespace c2f;
using namespace c2f::vision;

TEST_CASE("TSGO recovers a synthetic disparity map, flat and coarse to fine",
          "[stereo][pipeline]") {
  const test::SyntheticPair pair = test::synthetic_pair(96, 64, 3, 9, 42);
  TsgoOptions tsgo;
  tsgo.labels = 16;
  const PairwiseEnergy energy = tsgo_energy(tsgo_cost(pair.left, pair.right, tsgo), tsgo);
  const GridShape shape{96, 64};
  Options options;
  options.plateau_steps = {4};
  // The original problem ends where expansion has converged: a whole sweep without decrease.

  PartitionList flat;
  ExpansionSolver<> flat_solver;
  const Summary flat_summary = coarse_to_fine(energy, flat, flat_solver, options);
  ScheduleProvider paper(vision::parse_stereo_schedule("paper"), shape);
  ExpansionSolver<> c2f_solver;
  const Summary c2f_summary = coarse_to_fine(energy, paper, c2f_solver, options);

  const BadPixelRates flat_rates =
      bad_pixel_rates(labels_to_disparity(flat_summary.labeling, shape), pair.gt, pair.nonoccluded);
  const BadPixelRates c2f_rates =
      bad_pixel_rates(labels_to_disparity(c2f_summary.labeling, shape), pair.gt, pair.nonoccluded);
  INFO("flat: " << flat_rates.brief() << ", energy " << flat_summary.energy);
  INFO("c2f:  " << c2f_rates.brief() << ", energy " << c2f_summary.energy);
  CHECK(flat_rates.nonoccluded[1] < 0.05);
  CHECK(c2f_rates.nonoccluded[1] < 0.05);
  CHECK(c2f_summary.levels.size() == 4);
  // Both runs end in a local minimum of the same energy; coarse to fine may land in another one,
  // but not a much worse one (stated tolerance: 1% of the flat energy).
  CHECK(c2f_summary.energy <= flat_summary.energy * 1.01);
  CHECK(c2f_summary.energy == energy.evaluate(c2f_summary.labeling));
}

TEST_CASE("tsgo_problem is both TSGO steps plus the image that superpixel levels segment",
          "[stereo][pipeline]") {
  const test::SyntheticPair pair = test::synthetic_pair(96, 64, 3, 9, 42);
  TsgoOptions tsgo;
  tsgo.labels = 16;
  const TsgoProblem problem = tsgo_problem(pair.left, pair.right, tsgo);
  const PairwiseEnergy steps = tsgo_energy(tsgo_cost(pair.left, pair.right, tsgo), tsgo);
  REQUIRE(problem.energy.num_variables() == steps.num_variables());
  REQUIRE(problem.energy.num_labels() == steps.num_labels());
  const Labeling argmin = initial_labeling(steps, InitialLabeling::unary_argmin);
  CHECK(problem.energy.evaluate(argmin) == steps.evaluate(argmin));
  CHECK(problem.guide.size() == pair.left.size());

  const GridShape shape{96, 64};
  ScheduleProvider slic(vision::parse_stereo_schedule("slic:8 flat"), shape,
                        slic_source(problem.guide));
  ExpansionSolver<> solver;
  Options options;
  options.plateau_steps = {4};
  const Summary summary = coarse_to_fine(problem.energy, slic, solver, options);
  REQUIRE(summary.levels.size() == 2);
  CHECK(summary.levels.front().num_variables < problem.energy.num_variables());
  CHECK(summary.energy == problem.energy.evaluate(summary.labeling));
}
