#include "run_flags.hpp"

#include <cstddef>
#include <stdexcept>

#include "c2f/support/number_text.hpp"

namespace c2f::examples {

void RunFlags::declare(ToolOptions& options) {
  near_seeds_help_ =
      "where --near-radius's moves start: label_and_cheapest (the variables of that label and "
      "those whose cheapest cost it is), label (the variables of that label only: the edges of "
      "its regions, what is left to do after a coarse level on noisy unaries) or "
      "label_and_adjacent (as label, and on " +
      std::to_string(kMinLabelsForAdjacentSeeds) +
      " labels or more without shift moves also the variables of the labels next to it, so a "
      "region one label off moves as a whole)";
  if (seeds_depend_on_grid(defaults_)) {
    near_seeds_help_ += std::string("; default ") +
                        std::string(to_string(defaults_.near_seeds_on(true))) +
                        " on a pixel grid, " +
                        std::string(to_string(defaults_.near_seeds_on(false))) + " elsewhere";
  }
  plateau_tolerance_help_ =
      "on coarse levels, a decrease over the --plateau steps counts only when larger than this "
      "fraction of the energy, in [0, 1) (e.g. 1e-4: leave a level whose energy merely creeps "
      "down)";
  if (tolerance_depends_on_grid(defaults_)) {
    plateau_tolerance_help_ += "; default " + format_real(defaults_.plateau_tolerance_on(true)) +
                               " on a pixel grid, " +
                               format_real(defaults_.plateau_tolerance_on(false)) + " elsewhere";
  }
  options
      .text("solver", &solver_,
            "expansion (QPBO where a move is not submodular), swap (semi-metric terms only), lbp "
            "or icm")
      .text("maxflow", &maxflow_,
            "max-flow backend of expansion and swap: dynamic (ours: resumes each label's move "
            "from its previous flow), boost (Boost Graph's Boykov-Kolmogorov) or kolmogorov "
            "(GPL-3 libmaxflow, only in builds configured with -DC2F_WITH_KOLMOGOROV_MAXFLOW=ON)")
      .real("memory", &memory_gib_, {0.0, 65536.0},
            "GiB the whole run may take: the energy and the solver's working memory first, what "
            "they leave for the move graphs the dynamic backend recycles per label and for "
            "coarse levels (0: a quarter of this machine's memory, growing to the run's needs "
            "up to half, at most what is available; a run whose floor does not fit is refused "
            "before it allocates)")
      .text("graph-memory", &graph_memory_text_,
            "at most this many GiB of the budget for recycled move graphs (0: no recycling; "
            "default: all the budget leaves)")
      .integer("threads", &threads_, {0, 1024},
               "threads of the run, data preparation and solve (0: the machine's cores); the "
               "result is the same for every count")
      .integer("regions", &regions_, {1, 65535},
               "expansion with --near-radius: cut the variables into at most this many bands (at "
               "least 4096 variables each) and make near and shift moves on the even bands at "
               "once, then on the odd ones, on --threads threads; when a sweep gains at most 1e-4 "
               "of the energy, a sweep of band moves over every variable, then one of whole moves "
               "(convergence: four sweeps without decrease; e.g. 16). 1: every move on one thread")
      .integer("flow-parts", &flow_parts_, {0, 255},
               "expansion with --maxflow dynamic: solve the max-flow of every move in this many "
               "bands of its variables (at least 4096 each) at once on --threads threads, then "
               "over the whole graph from their flows; exact moves, the same output for every "
               "thread count (the bits may differ from 1 part's by floating-point rounding); 0: "
               "with --maxflow dynamic the most parts up to 4 that keep at most 5% of the "
               "energy's edges between parts, else 1 (e.g. a random graph), 1 with another; 1: "
               "one part "
               "(docs/performance.md, \"The solve\")")
      .text("bp-schedule", &bp_schedule_,
            "lbp: sequential (variables in index order, each with the newest messages), "
            "parallel (every message from the previous iteration's) or bands (bands of "
            "consecutive variables, sequential within each, the messages between bands from the "
            "previous iteration, the bands at once on --threads threads; the same output for "
            "every thread count); default bands")
      .integer("near-radius", &near_radius_, {0, 1000000},
               "expansion: 0 (every move may change every variable) or r: a move to a label frees "
               "only the variables within r edges of that label (or, with --near-seeds "
               "label_and_cheapest, of a pixel whose cheapest cost it is), with a sweep of whole "
               "moves whenever a sweep of such moves gains at most 1e-4 of the energy "
               "(convergence: three sweeps without decrease)")
      .text("near-seeds", &near_seeds_, near_seeds_help_.c_str())
      .text("near-graphs", &near_graphs_,
            "where --near-radius's moves are made: local (only on an energy whose edges are "
            "local in its variables' order: at most 5% of them between 4 equal ranges of "
            "indices, as on a pixel grid or lattice; elsewhere, e.g. on a random graph, where a "
            "few rounds of neighbours reach nearly every variable, every move is a whole move) "
            "or any")
      .integer("near-min-variables", &near_min_variables_, {0, 4'000'000'000},
               "make --near-radius's moves only on an energy of at least this many variables "
               "(0: any size); on a smaller one every move is a whole move (recycling its "
               "graph, which is cheap there); a --near-radius other than the default makes "
               "near moves at any size unless this is given too")
      .on_off_auto("shift-moves", &shift_moves_,
                   "expansion: every sweep begins with two moves in which every variable may step "
                   "one label up, then down, at once (moves regions that are off by one label, "
                   "e.g. one disparity; convergence: no expansion or shift move helps); "
                   "--shift-moves=off makes none; auto makes them only on an energy where some "
                   "expansion move is not submodular (a term that is no metric, e.g. truncated "
                   "quadratic or TSGO's step)")
      .text("near-levels", &near_levels_,
            "where --near-radius and --shift-moves apply: original (the default: the original "
            "problem only; coarse levels make whole moves, the faster coarse-to-fine run, "
            "docs/results.md) or all")
      .text("label-order", &label_order_,
            "order of expansion / swap moves (icm: of the variables): sequential (0, 1, ...), "
            "random, or frequency (labels of most variables first, counted when each level "
            "starts)")
      .real("time-limit", &time_limit_, kTimeLimitRange, "seconds on the run clock (0: none)")
      .integer("max-steps", &max_steps_, {0, kMaxSteps}, "solver steps in the whole run (0: none)")
      .text("plateau", &plateau_,
            "refine a coarse level after this many steps without decrease; rate: after the "
            "defaults' number of such steps, or sooner, after its first sweep, once its energy "
            "decrease per variable moved over its last 4 steps is no more than what the "
            "original problem is expected to give (what single-variable changes of the "
            "labeling it would hand down would gain, over a sweep of whole moves on the "
            "original variables)")
      .text("plateau-tolerance", &plateau_tolerance_, plateau_tolerance_help_.c_str())
      .integer("final-plateau", &final_plateau_, {0, kMaxSteps},
               "stop after this many steps without decrease on the original problem (0: one "
               "sweep: labels moves for expansion, three times that with --near-radius, label "
               "pairs for swap, 4 iterations for lbp, 1 for icm)");
}

SolverSpec RunFlags::solver_spec(bool on_grid) const {
  const SolverKind kind = with_flag("--solver", [&] { return solver_kind_from_string(solver_); });
  const VisitOrder order =
      with_flag("--label-order", [&] { return visit_order_from_string(label_order_); });
  const NearLevels levels =
      near_levels_.empty()
          ? NearLevels::original
          : with_flag("--near-levels", [&] { return near_levels_from_string(near_levels_); });
  if (!near_levels_.empty() && near_radius_ == 0 && shift_moves_ == "off")
    throw std::invalid_argument(
        "--near-levels: has no effect without --near-radius or --shift-moves");
  // The flags that may have asked for what the solver lacks, e.g. "--near-radius or
  // --label-order with --solver swap: ...".
  // Near and shift moves are expansion's: other solvers leave the defaults aside, and refuse
  // values that differ from them.
  const bool near_radius_given = near_radius_ != defaults_.near_radius;
  const NearSeeds default_seeds = defaults_.near_seeds_on(on_grid);
  const NearSeeds seeds = near_seeds_.empty() ? default_seeds : with_flag("--near-seeds", [&] {
    return near_seeds_from_string(near_seeds_);
  });
  if (near_radius_ == 0 && seeds != default_seeds)
    throw std::invalid_argument("--near-seeds: has no effect without --near-radius");
  const bool only_if_local =
      with_flag("--near-graphs", [&] { return near_only_if_local_from_string(near_graphs_); });
  if (near_radius_ == 0 && only_if_local != defaults_.near_moves_only_if_local)
    throw std::invalid_argument("--near-graphs: has no effect without --near-radius");
  // The defaults' size floor belongs to the defaults' near moves: --near-radius alone makes
  // near moves on an energy of any size.
  const bool min_variables_given =
      static_cast<std::size_t>(near_min_variables_) != defaults_.near_moves_min_variables;
  if (near_radius_ == 0 && min_variables_given)
    throw std::invalid_argument("--near-min-variables: has no effect without --near-radius");
  const std::size_t min_variables =
      min_variables_given || !near_radius_given ? static_cast<std::size_t>(near_min_variables_) : 0;
  const bool shift_moves_given = shift_moves_ != shift_moves_value(defaults_);
  const auto refuse = [&](const std::string& problem) {
    std::string flags = near_radius_given ? "--near-radius" : "";
    if (shift_moves_given) flags += flags.empty() ? "--shift-moves" : ", --shift-moves";
    flags += flags.empty() ? "--label-order" : " or --label-order";
    throw std::invalid_argument(flags + " with --solver " + solver_ + ": " + problem);
  };
  if (kind != SolverKind::expansion && near_radius_ != 0 && near_radius_given)
    refuse("near moves are expansion moves; solver '" + solver_ + "' has none");
  if (kind != SolverKind::expansion && shift_moves_ != "off" && shift_moves_given)
    refuse("shift moves are made by expansion; solver '" + solver_ + "' has none");
  if (kind != SolverKind::expansion && regions_ != ExpansionOptions{}.regions)
    throw std::invalid_argument("--regions with --solver " + solver_ +
                                ": region moves are expansion moves; solver '" + solver_ +
                                "' has none");
  if (regions_ > 1 && near_radius_ == 0)
    throw std::invalid_argument("--regions: has no effect without --near-radius");
  if (kind != SolverKind::lbp && !bp_schedule_.empty())
    throw std::invalid_argument("--bp-schedule with --solver " + solver_ +
                                ": it schedules loopy BP's messages; solver '" + solver_ +
                                "' sends none");
  if (kind != SolverKind::expansion && flow_parts_ != ExpansionOptions{}.flow_parts)
    throw std::invalid_argument("--flow-parts with --solver " + solver_ +
                                ": it solves expansion's moves; solver '" + solver_ + "' has none");

  SolverSpec spec;
  spec.maxflow = with_flag("--maxflow", [&] { return maxflow_kind_from_string(maxflow_); });
  if (flow_parts_ > 1 && spec.maxflow != MaxFlowKind::dynamic) {
    throw std::invalid_argument(
        "--flow-parts: only our max-flow (--maxflow dynamic) solves in "
        "parts, and --maxflow is " +
        maxflow_);
  }
  if (!maxflow_available(spec.maxflow)) {
    throw std::invalid_argument("--maxflow " + maxflow_ +
                                ": not in this build (configure with "
                                "-DC2F_WITH_KOLMOGOROV_MAXFLOW=ON)");
  }
  switch (kind) {
    case SolverKind::expansion: {
      ExpansionOptions options;
      options.order = order;
      options.near_radius = near_radius_;
      options.near_seeds = seeds;
      options.near_moves_only_if_local = only_if_local;
      options.near_moves_min_variables = min_variables;
      options.shift_moves = shift_moves_ == "on";
      options.shift_moves_unless_submodular = shift_moves_ == "auto";
      options.regions = regions_;
      options.threads = threads_;
      options.flow_parts = flow_parts_;
      spec = expansion_spec(options, levels, spec.maxflow);
      break;
    }
    case SolverKind::swap: {
      SwapOptions options;
      options.order = order;
      spec.original = options;
      break;
    }
    case SolverKind::lbp:
      if (order != VisitOrder::sequential) {
        refuse("lbp visits every message in every step; the order '" + label_order_ +
               "' applies to expansion, swap and icm");
      }
      spec.original = LbpOptions{
          .schedule = bp_schedule_.empty()
                          ? LbpOptions{}.schedule
                          : with_flag("--bp-schedule",
                                      [&] { return bp_schedule_from_string(bp_schedule_); }),
          .threads = threads_};
      break;
    case SolverKind::icm: {
      if (order == VisitOrder::frequency)
        refuse("the order 'frequency' orders labels (expansion, swap); icm visits variables");
      IcmOptions options;
      options.order = order;
      spec.original = options;
      break;
    }
  }
  if (const std::string problem = spec.validate(); !problem.empty()) refuse(problem);
  return spec;
}

Options RunFlags::limits(bool on_grid) const {
  Options options;
  if (plateau_ == "rate") {
    options.plateau_steps = {defaults_.plateau_steps};
  } else {
    const IntegerRange range{1, kMaxSteps};
    try {
      options.plateau_steps = {
          static_cast<int>(parse_integer_option("--plateau", plateau_, range))};
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument("--plateau: expected " + describe(range) + " or rate, got '" +
                                  plateau_ + "'");
    }
  }
  options.plateau_tolerance =
      plateau_tolerance_.empty()
          ? defaults_.plateau_tolerance_on(on_grid)
          : parse_real_option("--plateau-tolerance", plateau_tolerance_, {0.0, 1.0, false, true});
  options.plateau_steps_at_original = final_plateau_;
  options.time_limit_seconds = time_limit_;
  options.max_total_steps = max_steps_;
  return options;
}

RunConfig RunFlags::config(bool on_grid) const {
  RunConfig config;
  config.solver = solver_spec(on_grid);
  config.limits = limits(on_grid);
  config.progress_rate = plateau_ == "rate";
  config.memory = memory_gib_ == 0.0
                      ? default_memory_budget()
                      : memory_budget_of_gib(memory_gib_, "--memory " + format_real(memory_gib_));
  if (!graph_memory_text_.empty()) {
    const double gib = parse_real_option("--graph-memory", graph_memory_text_, {0.0, 65536.0});
    config.graph_memory = static_cast<std::size_t>(gib * static_cast<double>(std::size_t{1} << 30));
  }
  return config;
}

std::string near_and_shift_moves_text(const SolverSpec& spec) {
  const auto* options = std::get_if<ExpansionOptions>(&spec.original);
  if (options == nullptr) return {};
  std::string moves;
  if (options->near_radius > 0) {
    moves = near_moves_text(options->near_radius, options->near_seeds);
    if (options->near_moves_only_if_local) moves += " where the edges are local";
    if (options->near_moves_min_variables > 0) {
      moves += " on energies of at least " + std::to_string(options->near_moves_min_variables) +
               " variables";
    }
  }
  if (options->shift_moves) moves += moves.empty() ? "shift moves" : " and shift moves";
  if (moves.empty()) return {};
  return ", " + moves + (spec.coarse ? " on the original problem only" : " on every level");
}

}  // namespace c2f::examples
