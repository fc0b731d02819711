// The run layer's entry points: run() is coarse_to_fine with the solver a SolverSpec names,
// within a memory budget it plans, and reports what was given and used; every refusal names
// its field; the segmentation recipe runs cooperative cuts and Potts as c2f-segment does, and
// the stereo recipe a TSGO energy over a stereo schedule.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/lift/partition_list.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/run/coop_run.hpp"
#include "c2f/run/run.hpp"
#include "c2f/run/run_error.hpp"
#include "c2f/run/segmentation_run.hpp"
#include "c2f/run/stereo_run.hpp"
#include "c2f/vision/segmentation/segmentation_energy.hpp"
#include "c2f/vision/segmentation/segmentation_schedules.hpp"
#include "c2f/vision/stereo/stereo_schedules.hpp"
#include "c2f/vision/superpixels.hpp"
#include "support/random_models.hpp"
#include "support/synthetic_segmentation.hpp"
#include "support/synthetic_stereo.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

/// The energies after every step of a run.
struct EnergyTrace {
  std::vector<double> energies;
  Observer observer() {
    return [this](const StepEvent& event) {
      energies.push_back(event.energy);
      return ObserverDecision::continue_run;
    };
  }
};

/// The error run() threw for `config`, or fails.
template <class Energy, class Config>
RunConfigError refusal(const Energy& energy, const Config& config) {
  PartitionList flat;
  try {
    (void)run(energy, flat, config);
  } catch (const RunConfigError& error) {
    return error;
  }
  FAIL("the run was not refused");
  return RunConfigError("", "");
}

/// A synthetic segmentation (write_synthetic_segmentation in `dir`), its problem with the
/// default parameters and preparation, and the `paper` schedule for its labels.
struct SegmentationCase {
  vision::SegmentationScene scene;
  vision::SegmentationProblem problem;
  Schedule schedule;
};

SegmentationCase segmentation_case(const std::filesystem::path& dir, int width, int height,
                                   std::uint64_t seed, double noise = 18.0) {
  const SegmentationFilesOnDisk files =
      write_synthetic_segmentation(dir, width, height, seed, noise);
  vision::SegmentationScene scene = vision::load_segmentation_scene(
      {files.image, files.seeds, "", vision::SeedConvention::colours});
  vision::SegmentationProblem problem =
      vision::segmentation_problem(scene, CoopParameters{}, vision::DataPreparation{});
  Schedule schedule = vision::parse_segmentation_schedule("paper", scene.num_labels());
  return {std::move(scene), std::move(problem), std::move(schedule)};
}

/// The message of the RunConfigError run_segmentation threw for `config` over `schedule`'s
/// levels, or fails.
std::string segmentation_refusal(const vision::SegmentationProblem& problem,
                                 const Schedule& schedule, GridShape shape,
                                 const vision::SegmentationRunConfig& config) {
  ScheduleProvider levels(schedule, shape);
  try {
    (void)vision::run_segmentation(problem, levels, config);
  } catch (const RunConfigError& error) {
    return error.what();
  }
  FAIL("the run was not refused");
  return "";
}

}  // namespace

TEST_CASE("run() reports each step's variables and decides near moves on the energy", "[run]") {
  Rng rng(33);
  // A 60 x 40 grid (local: 3 x 60 of its 4700 edges join its four bands of rows) and a random
  // graph of as many variables (not local).
  const PairwiseEnergy grid = random_grid_energy(rng, 60, 40, 4);
  const PairwiseEnergy random = random_energy(rng, 2400, 4, 4800);
  ExpansionOptions near;
  near.near_radius = 2;
  near.near_seeds = NearSeeds::label;
  near.near_moves_only_if_local = true;
  RunConfig config;
  config.solver = expansion_spec(near);
  config.limits.max_total_steps = 60;
  const DensePartition coarse = random_partition(rng, grid.num_variables(), 50);

  struct Seen {
    std::vector<std::size_t> variables, step_variables;
    std::vector<long> steps;
  };
  const auto steps_of = [&](const PairwiseEnergy& energy, std::vector<DensePartition> partitions,
                            RunReport& report) {
    Seen seen;
    PartitionList levels(std::move(partitions));
    report = run(energy, levels, config, [&](const StepEvent& event) {
      seen.variables.push_back(event.num_variables);
      seen.step_variables.push_back(event.step_variables);
      seen.steps.push_back(event.step);
      return ObserverDecision::continue_run;
    });
    return seen;
  };
  RunReport report;
  const Seen on_grid = steps_of(grid, {coarse}, report);
  CHECK(report.near_radius == 2);
  CHECK(report.near_seeds == NearSeeds::label);
  CHECK_THAT(report.threads_line(),
             Catch::StartsWith("solve: near moves of radius 2 from their label (whole moves "
                               "where they stall)"));
  std::size_t near_steps = 0;
  for (std::size_t k = 0; k < on_grid.steps.size(); ++k) {
    INFO("event " << k);
    if (on_grid.steps[k] == 0) {
      CHECK(on_grid.step_variables[k] == 0);
    } else if (on_grid.variables[k] < grid.num_variables()) {
      CHECK(on_grid.step_variables[k] == on_grid.variables[k]);  // whole moves on coarse levels
    } else {
      CHECK(on_grid.step_variables[k] <= grid.num_variables());
      near_steps += on_grid.step_variables[k] < grid.num_variables();
    }
  }
  CHECK(near_steps > 0);

  const Seen on_random = steps_of(random, {}, report);
  CHECK(report.near_radius == 0);  // not local: whole moves
  CHECK_THAT(report.threads_line(), !Catch::Contains("near moves"));
  for (std::size_t k = 0; k < on_random.steps.size(); ++k)
    CHECK(on_random.step_variables[k] == (on_random.steps[k] == 0 ? 0 : random.num_variables()));

  // Seeds the grid's 4 labels narrow (near_seeds_in_use) are reported as used: from the label.
  std::get<ExpansionOptions>(config.solver.original).near_seeds = NearSeeds::label_and_adjacent;
  const Seen narrowed = steps_of(grid, {coarse}, report);
  CHECK(report.near_seeds == NearSeeds::label);
  CHECK_THAT(report.threads_line(),
             Catch::StartsWith("solve: near moves of radius 2 from their label (whole moves "));
  CHECK(narrowed.step_variables == on_grid.step_variables);  // the same moves as 'label'

  // Below near_moves_min_variables the grid gets whole moves too.
  std::get<ExpansionOptions>(config.solver.original).near_moves_min_variables =
      grid.num_variables() + 1;
  const Seen small_grid = steps_of(grid, {coarse}, report);
  CHECK(report.near_radius == 0);
  CHECK_THAT(report.threads_line(), !Catch::Contains("near moves"));
  for (std::size_t k = 0; k < small_grid.steps.size(); ++k)
    CHECK(small_grid.step_variables[k] == (small_grid.steps[k] == 0 ? 0 : small_grid.variables[k]));
}

TEST_CASE("run() is coarse_to_fine with the solver the spec names, step for step", "[run]") {
  Rng rng(31);
  const PairwiseEnergy energy = random_grid_energy(rng, 16, 12, 5);
  const DensePartition coarse = random_partition(rng, energy.num_variables(), 40);
  ExpansionOptions near;
  near.near_radius = 1;
  near.order = VisitOrder::random;
  RunConfig config;
  config.solver = expansion_spec(near);
  config.limits.plateau_steps = {3};
  config.limits.max_total_steps = 60;

  EnergyTrace by_run, by_hand;
  PartitionList levels({coarse});
  const RunReport report = run(energy, levels, config, by_run.observer());
  ExpansionOptions whole = near;
  whole.near_radius = 0;
  // The run layer sets the graph-cut solvers' limit from the budget: the same limit by hand.
  whole.graph_memory_limit = near.graph_memory_limit = report.plan.graph_memory;
  whole.problem_memory_limit = near.problem_memory_limit = report.plan.problem_memory;
  ExpansionSolver<> coarse_solver(whole), original_solver(near);
  PartitionList same_levels({coarse});
  const Summary summary =
      coarse_to_fine(energy, same_levels, LevelSolvers(coarse_solver, original_solver),
                     config.limits, by_hand.observer());
  CHECK(by_run.energies == by_hand.energies);
  CHECK(report.summary.labeling == summary.labeling);
  CHECK(report.summary.energy == summary.energy);

  // What was given and used: the machine's default budget, a floor within it, the graphs
  // within their limit.
  CHECK(report.budget.bytes == default_memory_budget().bytes);
  CHECK(report.plan.floor > 0);
  CHECK(report.plan.floor <= report.plan.budget);
  CHECK(report.plan.problem_memory > 0);
  CHECK(report.plan.graph_memory ==
        report.plan.budget - report.plan.floor - report.plan.problem_memory);
  CHECK(report.recycles);
  CHECK(report.optional_memory_used > 0);
  CHECK(report.optional_memory_used <= report.plan.graph_memory + report.plan.problem_memory);
  CHECK_THAT(report.memory_line(), Catch::StartsWith("memory budget ") &&
                                       Catch::Contains(", recycled move graphs up to "));
  CHECK_THAT(report.memory_report(), Catch::Contains(", floor ") && Catch::Contains(" used"));
}

TEST_CASE("run() reports loopy BP's schedule, bands and threads", "[run][lbp]") {
  Rng rng(32);
  const PairwiseEnergy energy = random_grid_energy(rng, 100, 90, 4);  // 9000 variables
  RunConfig config;
  config.limits.max_total_steps = 4;
  const auto report_of = [&](BpSchedule schedule, int threads, std::size_t band_variables) {
    LbpOptions lbp{schedule, 0.0};
    lbp.threads = threads;
    lbp.band_variables = band_variables;
    config.solver.original = lbp;
    PartitionList flat;
    return run(energy, flat, config);
  };
  const RunReport bands = report_of(BpSchedule::bands, 3, 0);
  CHECK(bands.bp_band_variables == LbpOptions::kMinBandVariables);  // 3 bands
  CHECK(bands.threads_line() == "solve: BP messages by bands of 4096 variables on 3 threads");
  // No more threads than bands.
  CHECK(report_of(BpSchedule::bands, 3, 5000).threads_line() ==
        "solve: BP messages by bands of 5000 variables on 2 threads");
  CHECK(report_of(BpSchedule::sequential, 3, 0).threads_line() ==
        "solve: BP messages in variable order on one thread");
  CHECK(report_of(BpSchedule::parallel, 2, 0).threads_line() ==
        "solve: BP messages from the previous iteration's on 2 threads");
  CHECK(report_of(BpSchedule::bands, 1, 0).summary.labeling == bands.summary.labeling);
  CHECK(detail::partition_threads(LbpOptions{.threads = 2}) == 2);
}

TEST_CASE("a run's graph memory is what the budget leaves, at most what the config says",
          "[run][memory]") {
  Rng rng(32);
  const PairwiseEnergy energy = random_grid_energy(rng, 12, 10, 4);
  RunConfig config;
  const auto floor = run_memory_floor(config.solver, problem_size(energy));
  REQUIRE(floor);
  const std::size_t problems = *kept_problem_bytes(ExpansionOptions{}, problem_size(energy));
  config.memory = MemoryBudget{*floor + problems + 100000, "a test"};
  PartitionList flat;
  const RunReport roomy = run(energy, flat, config);
  CHECK(roomy.plan.problem_memory == problems);
  CHECK(roomy.plan.graph_memory == 100000);
  config.graph_memory = 0;  // no recycled graphs: the kept problems only, the same result
  PartitionList again;
  const RunReport without = run(energy, again, config);
  CHECK(without.plan.graph_memory == 0);
  CHECK(without.optional_memory_used == problems);
  CHECK(without.summary.labeling == roomy.summary.labeling);
  // LBP and ICM keep nothing and say so.
  config.solver.original = IcmOptions{};
  PartitionList icm_levels;
  const RunReport icm = run(energy, icm_levels, config);
  CHECK_FALSE(icm.recycles);
  CHECK(icm.memory_line().find("recycled") == std::string::npos);
}

TEST_CASE("every refusal of the run layer names its field", "[run][validation]") {
  Rng rng(33);
  const PairwiseEnergy energy = random_grid_energy(rng, 8, 6, 3);
  RunConfig config;
  config.solver.original = LbpOptions{BpSchedule::sequential, 1.5};
  RunConfigError error = refusal(energy, config);
  CHECK(error.field() == "solver.original");
  CHECK(error.problem() == "damping must be in [0, 1)");
  CHECK(std::string(error.what()) == "solver.original: damping must be in [0, 1)");

  config = RunConfig{};
  config.limits.time_limit_seconds = -1;
  error = refusal(energy, config);
  CHECK(error.field() == "limits");
  CHECK_THAT(error.problem(), Catch::StartsWith("time_limit_seconds must be finite"));

  config = RunConfig{};
  config.limits.coarse_level_fits = [](std::size_t) { return true; };
  CHECK(refusal(energy, config).field() == "limits");

  config = RunConfig{};
  config.memory = MemoryBudget{1024, "a tiny budget"};
  config.energy_name = "the test energy";
  error = refusal(energy, config);
  CHECK(error.field() == "memory");
  CHECK_THAT(error.problem(),
             Catch::StartsWith("the test energy needs ") && Catch::EndsWith("(a tiny budget)"));

  CoopRunConfig coop;
  coop.solver.expansion_cycles = -1;
  CHECK(refusal(random_coop_energy(rng, 6, 5, 3, 2), coop).field() == "solver");
}

TEST_CASE("the segmentation recipe runs either method within the budget, as built by hand",
          "[run][segmentation]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segmentation-run";
  const auto [scene, problem, schedule] = segmentation_case(dir, 48, 36, 5);

  for (const auto method : {vision::SegmentationMethod::coop, vision::SegmentationMethod::potts}) {
    vision::SegmentationRunConfig config;
    config.method = method;
    EnergyTrace by_recipe, by_hand;
    ScheduleProvider levels(schedule, scene.shape());
    const RunReport report =
        vision::run_segmentation(problem, levels, config, by_recipe.observer());
    ScheduleProvider same_levels(schedule, scene.shape());
    Options options;
    if (method == vision::SegmentationMethod::potts) {
      ExpansionOptions expansion;
      expansion.graph_memory_limit = report.plan.graph_memory;
      expansion.problem_memory_limit = report.plan.problem_memory;
      ExpansionSolver<> solver(expansion);
      options.plateau_steps = {vision::coarse_plateau_steps(
          solver.quiet_steps_to_converge(problem.potts), scene.num_labels(), false)};
      coarse_to_fine(problem.potts, same_levels, solver, options, by_hand.observer());
    } else {
      CoopSolver solver;
      options.plateau_steps = {vision::coarse_plateau_steps(
          solver.quiet_steps_to_converge(problem.coop), scene.num_labels(), false)};
      coarse_to_fine(problem.coop, same_levels, solver, options, by_hand.observer());
    }
    CHECK(by_recipe.energies == by_hand.energies);
    CHECK(report.summary.reason == TerminationReason::converged);
    CHECK(report.plan.floor <= report.plan.budget);
  }
  vision::SegmentationRunConfig bad;
  bad.plateau = -2;
  CHECK_THAT(segmentation_refusal(problem, schedule, scene.shape(), bad),
             Catch::StartsWith("plateau: expected -1"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("the segmentation recipe makes near moves on the original problem only",
          "[run][segmentation][near]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segmentation-near";
  // Noisy colours, so that the levels' moves have work to do.
  const auto [scene, problem, schedule] = segmentation_case(dir, 64, 48, 4, 90.0);
  vision::SegmentationRunConfig config;
  config.coop.near_radius = 1;
  EnergyTrace by_recipe, original_only, every_level;
  ScheduleProvider levels(schedule, scene.shape());
  const RunReport report = vision::run_segmentation(problem, levels, config, by_recipe.observer());
  CHECK(report.near_radius == 1);
  CHECK(report.near_seeds == NearSeeds::label);
  CHECK_THAT(report.threads_line(), Catch::StartsWith("solve: near moves of radius 1"));
  const auto by_hand = [&](std::size_t near_floor, EnergyTrace& trace) {
    CoopSolverOptions options = config.coop;
    options.near_moves_min_variables = near_floor;
    CoopSolver solver(options);
    Options limits;
    limits.plateau_steps = {vision::coarse_plateau_steps(
        solver.quiet_steps_to_converge(problem.coop), scene.num_labels(), false)};
    ScheduleProvider same_levels(schedule, scene.shape());
    coarse_to_fine(problem.coop, same_levels, solver, limits, trace.observer());
  };
  by_hand(problem.coop.num_variables(), original_only);
  by_hand(0, every_level);
  CHECK(by_recipe.energies == original_only.energies);
  // Near moves on the coarse levels too would take another path on this scene.
  CHECK(by_recipe.energies != every_level.energies);
  std::filesystem::remove_all(dir);
}

TEST_CASE("the segmentation defaults make near moves with majorise-minimise only",
          "[run][segmentation][defaults]") {
  const vision::SegmentationDefaults defaults = vision::segmentation_defaults();
  CHECK(defaults.method == vision::SegmentationMethod::coop);
  CHECK(defaults.strategy == AuxStrategy::mm);
  CHECK(defaults.mm_near_radius > 0);
  CHECK(defaults.config().coop.strategy == AuxStrategy::mm);
  CHECK(defaults.config().coop.near_radius == defaults.mm_near_radius);
  for (const AuxStrategy aux : {AuxStrategy::greedy, AuxStrategy::ceres}) {
    CHECK(defaults.config(aux).coop.strategy == aux);
    CHECK(defaults.config(aux).coop.near_radius == 0);
  }
  CHECK(defaults.config().validate().empty());
  CHECK_NOTHROW(vision::parse_segmentation_schedule(defaults.schedule, 3));
}

TEST_CASE("the segmentation run gives the same bits on 1, 2 and 3 threads, either method",
          "[run][segmentation][threads]") {
  // 128 x 96 pixels: each move's max-flow in 3 parts (at least 4096 variables per part).
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segmentation-threads";
  const auto [scene, problem, schedule] = segmentation_case(dir, 128, 96, 4);
  for (const auto method : {vision::SegmentationMethod::coop, vision::SegmentationMethod::potts}) {
    std::optional<RunReport> serial;
    for (const int threads : {1, 2, 3}) {
      INFO("method " << vision::to_string(method) << ", threads " << threads);
      vision::SegmentationRunConfig config;
      config.method = method;
      config.threads = threads;
      ScheduleProvider levels(schedule, scene.shape());
      const RunReport report = vision::run_segmentation(problem, levels, config);
      CHECK(report.flow_parts == 3);
      CHECK(report.flow_threads == static_cast<unsigned>(threads));
      if (!serial) {
        serial = report;
        continue;
      }
      CHECK(report.summary.labeling == serial->summary.labeling);
      CHECK(report.summary.energy == serial->summary.energy);
      CHECK(report.summary.total_steps == serial->summary.total_steps);
    }
  }
  vision::SegmentationRunConfig bad;
  bad.threads = -1;
  CHECK_THAT(segmentation_refusal(problem, schedule, scene.shape(), bad),
             Catch::StartsWith("threads: expected >= 0"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("segmentation's levels keep seeds of two labels apart, so a stopped run keeps them",
          "[run][segmentation]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segmentation-seeds-apart";
  const int width = 96, height = 72;
  SegmentationCase built = segmentation_case(dir, width, height, 3);
  vision::SegmentationScene& scene = built.scene;
  // A second label's scribble two pixels beside the first label's, in the same flat region, so
  // that a SLIC superpixel holds seeds of both.
  const auto pixel = [&](int x, int y) { return static_cast<std::size_t>(y * width + x); };
  const int first = scene.seeds[pixel(width / 8, height / 2)];
  REQUIRE(first != vision::kNoLabel);
  const int other = (first + 1) % scene.num_labels();
  for (int y = height / 4; y <= height * 3 / 4; ++y) scene.seeds[pixel(width / 8 + 2, y)] = other;
  const vision::SegmentationProblem seeded =
      vision::segmentation_problem(scene, CoopParameters{}, vision::DataPreparation{});
  const auto groups_mixing_seeds = [&](const DensePartition& level) {
    std::size_t mixing = 0;
    for (std::size_t g = 0; g < level.num_groups(); ++g) {
      int label = vision::kNoLabel;
      bool mixed = false;
      for (const VariableIndex v : level.members(g)) {
        const int seed = scene.seeds[v];
        if (seed == vision::kNoLabel) continue;
        mixed = mixed || (label != vision::kNoLabel && seed != label);
        label = seed;
      }
      mixing += mixed ? 1 : 0;
    }
    return mixing;
  };
  const Schedule superpixels =
      vision::parse_segmentation_schedule("superpixels", scene.num_labels());
  ScheduleProvider plain(superpixels, scene.shape(), vision::slic_source(scene.image));
  REQUIRE(groups_mixing_seeds(*plain.next(seeded.coop)) > 0);  // the case at hand

  ScheduleProvider levels = vision::segmentation_levels(superpixels, scene);
  const auto coarse = levels.next(seeded.coop);
  const auto finer = levels.next(seeded.coop);
  REQUIRE((coarse && finer));
  CHECK(groups_mixing_seeds(*coarse) == 0);
  CHECK(groups_mixing_seeds(*finer) == 0);
  CHECK(finer->is_refinement_of(*coarse));

  for (const auto method : {vision::SegmentationMethod::coop, vision::SegmentationMethod::potts}) {
    INFO("method " << vision::to_string(method));
    vision::SegmentationRunConfig config;
    config.method = method;
    config.max_total_steps = 1;
    ScheduleProvider stopped = vision::segmentation_levels(superpixels, scene);
    const RunReport report = vision::run_segmentation(seeded, stopped, config);
    REQUIRE(report.summary.levels.size() == 1);  // stopped on the coarsest level
    std::size_t broken = 0;
    for (std::size_t v = 0; v < scene.seeds.size(); ++v) {
      if (scene.seeds[v] != vision::kNoLabel && report.summary.labeling[v] != scene.seeds[v])
        ++broken;
    }
    CHECK(broken == 0);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("the stereo recipe runs the TSGO energy over a stereo schedule, as built by hand",
          "[run][stereo]") {
  const SyntheticPair pair = synthetic_pair(64, 48, 3, 7, 11);
  vision::TsgoOptions tsgo;
  tsgo.labels = 10;
  const vision::TsgoProblem problem = vision::tsgo_problem(pair.left, pair.right, tsgo);
  const GridShape shape{64, 48};
  RunConfig config;
  config.limits.max_total_steps = 80;
  for (const char* text : {"paper", "paper-slic"}) {
    const Schedule schedule = vision::parse_stereo_schedule(text);
    EnergyTrace by_recipe, by_hand;
    const vision::StereoRunReport report =
        vision::run_stereo(problem, schedule, config, by_recipe.observer());
    ScheduleProvider levels(schedule, shape, vision::slic_source(problem.guide));
    const RunReport hand = run(problem.energy, levels, config, by_hand.observer());
    CHECK(by_recipe.energies == by_hand.energies);
    CHECK(report.run.summary.labeling == hand.summary.labeling);
    CHECK(report.levels.size() == levels.reports().size());
    CHECK(report.levels.size() == schedule.levels.size());
  }
  // The recipe's first step: the scene's problem as tsgo_problem builds it, on the threads asked.
  vision::StereoScene scene;
  scene.left = pair.left;
  scene.right = pair.right;
  tsgo.threads = 2;
  const vision::PreparedStereo prepared = vision::prepare_stereo(scene, tsgo);
  CHECK(prepared.threads == 2);
  const Labeling some(64 * 48, 3);
  CHECK(prepared.problem.energy.evaluate(some) == problem.energy.evaluate(some));
  CHECK(prepared.problem.energy.num_labels() == 10);
  tsgo.threads = 0;
  // Before anything is built: the larger of TSGO step 1's peak and the run's floor.
  const auto need = vision::stereo_memory_need(shape, tsgo, config.solver);
  REQUIRE(need.has_value());
  CHECK(*need ==
        std::max(*vision::tsgo_memory_estimate(64, 48, 10, tsgo.threads),
                 *run_memory_floor(config.solver,
                                   *grid_problem_size(64, 48, 10, CostStorage::single_precision))));
}

TEST_CASE("a coarse level whose fixed part fits runs with the recycled graphs it leaves room for",
          "[run][memory]") {
  Rng rng(34);
  const PairwiseEnergy energy = random_grid_energy(rng, 24, 20, 40);
  const ProblemSize size = problem_size(energy);
  // A level of almost every variable (the last ten join the first ten): its reduced energy and
  // solver take more than the original solver's share of the floor, so beside the whole graph
  // limit it would not fit.
  std::vector<int> ids(energy.num_variables());
  for (std::size_t v = 0; v < ids.size(); ++v)
    ids[v] = static_cast<int>(v < ids.size() - 10 ? v : v - (ids.size() - 10));
  const DensePartition coarse = DensePartition::from_ids(ids);
  RunConfig config;
  config.solver.original = ExpansionOptions{};
  config.graph_memory = 0;  // the plan's limit is set below through the budget instead
  const auto floor = run_memory_floor(config.solver, size);
  REQUIRE(floor);
  const std::size_t fixed = *coarse_level_memory(config.solver, size, coarse.num_groups(), 0, 0);
  const std::size_t with_graphs =
      *coarse_level_memory(config.solver, size, coarse.num_groups(), std::size_t{1} << 40, 0);
  REQUIRE(with_graphs > fixed);
  // Room for the fixed part and a little more, not for every graph.
  const std::size_t working =
      *working_memory_bytes(config.solver.original, MaxFlowKind::dynamic, size);
  REQUIRE(fixed > working);
  config.graph_memory.reset();
  config.memory = MemoryBudget{*floor + (fixed - working) + 4096, "a test"};
  PartitionList levels({coarse});
  EnergyTrace trace;
  const RunReport report = run(energy, levels, config, trace.observer());
  REQUIRE(report.summary.levels.size() == 2);
  CHECK_FALSE(report.summary.levels[0].skipped);
  CHECK(report.summary.levels[0].steps > 0);
  for (std::size_t i = 1; i < trace.energies.size(); ++i)  // the level switch: to rounding
    CHECK(trace.energies[i] <= trace.energies[i - 1] + 1e-9 * std::abs(trace.energies[i - 1]));
  // Where the fixed part does not fit, the level is skipped (and the run says so).
  config.memory = MemoryBudget{*floor + (fixed - working) / 2, "a test"};
  PartitionList same({coarse});
  CHECK(run(energy, same, config).summary.levels[0].skipped);
}

TEST_CASE("RunConfig::progress_rate leaves a coarse level the plateau rule would keep",
          "[run][rules]") {
  Rng rng(77);
  const PairwiseEnergy energy = random_grid_energy(rng, 12, 10, 6);
  // A coarse level of every variable on its own: as slow per step as the original problem, which
  // is expected to give what single-variable changes of the level's labeling would.
  const DensePartition singletons = DensePartition::identity(energy.num_variables());
  RunConfig config;
  config.limits.plateau_steps = {1000};
  config.limits.max_steps_per_level = 1000;
  PartitionList plain_levels({singletons});
  const RunReport plain = run(energy, plain_levels, config);
  REQUIRE(plain.summary.levels.size() == 2);
  CHECK(plain.summary.levels[0].steps == 1000);  // nothing but the step limit ends it
  config.progress_rate = true;
  PartitionList rated_levels({singletons});
  const RunReport rated = run(energy, rated_levels, config);
  REQUIRE(rated.summary.levels.size() == 2);
  // Compared from the end of the first sweep (6 moves) on: once the last moves stop decreasing
  // the energy, the level is left (at an expansion minimum no variable gains alone either, so
  // the original problem is expected to give nothing).
  CHECK(rated.summary.levels[0].steps >= 6);
  CHECK(rated.summary.levels[0].steps < 1000);
  CHECK(rated.summary.reason == TerminationReason::converged);
  CHECK(rated.summary.energy == energy.evaluate(rated.summary.labeling));
}
