#include "c2f/adapters/coop/coop_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/support/enum_names.hpp"
#include "coop_relaxation.hpp"

namespace c2f {

std::string_view to_string(AuxStrategy strategy) {
  switch (strategy) {
    case AuxStrategy::greedy:
      return "greedy";
    case AuxStrategy::mm:
      return "mm";
    case AuxStrategy::ceres:
      return "ceres";
  }
  return "unknown";
}

AuxStrategy aux_strategy_from_string(std::string_view text) {
  constexpr AuxStrategy kAll[] = {AuxStrategy::greedy, AuxStrategy::mm, AuxStrategy::ceres};
  return enum_from_string(text, kAll, "auxiliary-variable strategy");
}

std::string_view to_string(ExpansionStart start) {
  return start == ExpansionStart::zero ? "zero" : "current";
}

ExpansionStart expansion_start_from_string(std::string_view text) {
  constexpr ExpansionStart kAll[] = {ExpansionStart::zero, ExpansionStart::current};
  return enum_from_string(text, kAll, "expansion start");
}

std::string RelaxationOptions::validate() const {
  if (max_iterations < 1) return "relaxation.max_iterations must be >= 1";
  if (!(smoothing > 0.0 && smoothing <= 1.0)) return "relaxation.smoothing must be in (0, 1]";
  return {};
}

int CoopSolverOptions::cycles() const noexcept {
  if (expansion_cycles > 0) return expansion_cycles;
  return strategy == AuxStrategy::mm ? 1 : 10;
}

std::string CoopSolverOptions::validate() const {
  if (expansion_cycles < 0) return "expansion_cycles must be >= 0 (0: the strategy's own)";
  if (threads < 0) return "threads must be >= 0";
  if (near_radius < 0) return "near_radius must be >= 0";
  return relaxation.validate();
}

/// The ceres strategy's work array: the logits of the relaxation.
struct CoopSolver::Relaxation {
  std::vector<double> logits;
};

/// An alpha-expansion of E_h, with the energy it is bound to.
struct CoopSolver::KeptExpansion {
  CoopAuxiliary h;
  PairwiseEnergy pairwise;
  ExpansionSolver<> solver;
};

CoopSolver::CoopSolver(CoopSolverOptions options) : options_(options) {
  if (const std::string problem = options_.validate(); !problem.empty())
    throw std::invalid_argument("CoopSolverOptions: " + problem);
}

CoopSolver::~CoopSolver() = default;
CoopSolver::CoopSolver(CoopSolver&&) noexcept = default;
CoopSolver& CoopSolver::operator=(CoopSolver&&) noexcept = default;

std::size_t CoopSolver::quiet_steps_to_converge(const CoopEnergy& energy) const noexcept {
  switch (options_.strategy) {
    case AuxStrategy::greedy:
      return static_cast<std::size_t>(energy.num_labels() * energy.num_classes()) + 1;
    case AuxStrategy::mm:
      return 1;
    case AuxStrategy::ceres:
      return 2;
  }
  return 1;
}

void CoopSolver::bind(const CoopEnergy& energy, std::span<const Label> start) {
  validate_labeling(start, energy.num_variables(), energy.num_labels(), "CoopSolver::bind: start");
  energy_ = &energy;
  labeling_.assign(start.begin(), start.end());
  value_ = energy.evaluate_unchecked(labeling_);
  if (h_.num_labels() != energy.num_labels() || h_.num_classes() != energy.num_classes()) {
    h_ = CoopAuxiliary(energy.num_labels(), energy.num_classes());
    last_kept_flip_ = -1;
  }
  // The greedy scan resumes just after the last flip it kept (the reference does so when it
  // switches to the original problem).
  const auto flips = static_cast<std::size_t>(energy.num_labels() * energy.num_classes());
  next_flip_ = last_kept_flip_ < 0 ? 0 : (static_cast<std::size_t>(last_kept_flip_) + 1) % flips;
  tried_unchanged_ = false;
  quiet_for_.reset();
  expansion_.reset();
  last_ = {};
  if (options_.strategy == AuxStrategy::ceres) {
    relaxation_ = std::make_unique<Relaxation>();
    relaxation_->logits.assign(
        energy.num_variables() * static_cast<std::size_t>(energy.num_labels()), 0.0);
  }
}

double CoopSolver::step() {
  if (energy_ == nullptr) throw std::logic_error("CoopSolver::step: call bind() first");
  last_ = {};
  switch (options_.strategy) {
    case AuxStrategy::greedy:
      greedy_step();
      break;
    case AuxStrategy::mm:
      mm_step();
      break;
    case AuxStrategy::ceres:
      ceres_step();
      break;
  }
  return value_;
}

std::size_t CoopSolver::flow_parts(const CoopEnergy& energy) const {
  ExpansionOptions expansion_options;
  expansion_options.threads = options_.threads;
  const ExpansionSolver<> expansion(expansion_options);
  return expansion.flow_parts(
      pairwise_energy(energy, CoopAuxiliary(energy.num_labels(), energy.num_classes())));
}

Labeling CoopSolver::expand_for(const CoopAuxiliary& h, std::span<const Label> start) {
  const bool goes_on = expansion_ != nullptr && expansion_->h == h &&
                       std::ranges::equal(expansion_->solver.labeling(), start);
  if (!goes_on) {
    expansion_.reset();  // its graphs are freed before the next ones are built
    PairwiseEnergy pairwise = pairwise_energy(*energy_, h);
    // Of graph_memory_limit, a quarter may keep the move problems when all of them fit in it;
    // the recycled graphs get the rest.
    ExpansionOptions expansion_options;
    expansion_options.threads = options_.threads;
    // A step's expansion makes one cycle, or goes on for the next step: each label's move
    // solved on a graph of its own from zero flow, then resumed from it, beats re-solving the
    // other labels' graph (whose moves freed other variables).
    expansion_options.first_move_own_graph = true;
    expansion_options.near_radius = options_.near_radius;
    expansion_options.near_seeds = NearSeeds::label;
    expansion_options.near_moves_min_variables = options_.near_moves_min_variables;
    // A step that confirms convergence repeats the last whole sweep on E_h with little
    // changed: resumed from its graphs it costs a fraction of a sweep from zero flow.
    expansion_options.recycle_with_near_moves = true;
    const std::size_t problems = kept_problem_bytes(expansion_options, problem_size(pairwise))
                                     .value_or(static_cast<std::size_t>(-1));
    expansion_options.problem_memory_limit = options_.graph_memory_limit / 4;
    expansion_options.graph_memory_limit =
        options_.graph_memory_limit -
        (problems <= expansion_options.problem_memory_limit ? problems : 0);
    expansion_ = std::make_unique<KeptExpansion>(
        KeptExpansion{h, std::move(pairwise), ExpansionSolver<>(expansion_options)});
    expansion_->solver.bind(expansion_->pairwise, start);
  }
  ExpansionSolver<>& expansion = expansion_->solver;
  // A sweep is one move per label (no shift moves here). A cycle is one sweep of whole moves,
  // or one of near moves that lowered E_h; a near sweep that lowered nothing hands over to a
  // whole sweep (ExpansionSolver's rule), which then ends the cycle. So a cycle that lowers
  // nothing ends in a whole sweep that found nothing.
  const auto sweep = static_cast<std::size_t>(expansion_->pairwise.num_labels());
  expansion_ended_quiet_ = false;
  for (int cycle = 0; cycle < options_.cycles(); ++cycle) {
    bool improved = false, cycle_done = false;
    while (!cycle_done) {
      bool sweep_improved = false;
      for (std::size_t m = 0; m < sweep; ++m) {
        expansion.step();
        sweep_improved = sweep_improved || expansion.last_step().improved;
        ++last_.expansion_moves;
      }
      improved = improved || sweep_improved;
      cycle_done = !expansion.last_step().near || sweep_improved;
    }
    if (!improved) {
      expansion_ended_quiet_ = true;
      break;
    }
  }
  kept_bytes_ = std::max(kept_bytes_, expansion.kept_bytes());
  return Labeling(expansion.labeling().begin(), expansion.labeling().end());
}

void CoopSolver::keep_if_lower(Labeling candidate, const CoopAuxiliary& h) {
  const double candidate_value = energy_->evaluate_unchecked(candidate);
  if (!(candidate_value < value_)) return;
  for (std::size_t i = 0; i < candidate.size(); ++i) last_.changed += candidate[i] != labeling_[i];
  last_.improved = true;
  last_.aux_changes = h.differences(h_);
  labeling_ = std::move(candidate);
  value_ = candidate_value;
  h_ = h;
}

void CoopSolver::greedy_step() {
  CoopAuxiliary trial = h_;
  std::ptrdiff_t flip = -1;
  if (tried_unchanged_) {
    const int K = energy_->num_classes();
    flip = static_cast<std::ptrdiff_t>(next_flip_);
    const int label = static_cast<int>(next_flip_) / K;
    const int edge_class = static_cast<int>(next_flip_) % K;
    trial.set(label, edge_class, !trial.linear(label, edge_class));
    last_.flipped_label = label;
    last_.flipped_class = edge_class;
    next_flip_ = (next_flip_ + 1) % static_cast<std::size_t>(energy_->num_labels() * K);
  }
  tried_unchanged_ = true;
  const Labeling zero(labeling_.size(), 0);
  const std::span<const Label> start =
      options_.start == ExpansionStart::zero ? std::span<const Label>(zero) : labeling_;
  keep_if_lower(expand_for(trial, start), trial);
  if (last_.improved && flip >= 0) last_kept_flip_ = flip;
}

void CoopSolver::mm_step() {
  const CoopAuxiliary h = CoopAuxiliary::optimal_for(*energy_, labeling_);
  if (quiet_for_ && *quiet_for_ == h) {
    last_.known_quiet = true;
    return;
  }
  keep_if_lower(expand_for(h, labeling_), h);
  // The step is a function of (labeling, h). Not kept, the labeling is the same and so is the
  // next h: the next step would repeat this one. Kept from an expansion whose last cycle moved
  // nothing, the labeling is a fixed point of E_h's expansion, so a next step with the same h
  // would leave it as it is (no move lowers E_h by more than rounding). Either way it can be
  // skipped.
  if (!last_.improved || expansion_ended_quiet_) {
    quiet_for_ = h;
  } else {
    quiet_for_.reset();
  }
}

namespace {
/// How far ahead the kept labeling's label starts in the logits (softmax: p = e^2 / (e^2 + L - 1)).
constexpr double kStartMargin = 2.0;
}  // namespace

void CoopSolver::ceres_step() {
  const auto start = std::chrono::steady_clock::now();
  // Warm start: the logits of the previous step's solution, the labeling kept (its label ahead
  // by 2 at every variable).
  const auto L = static_cast<std::size_t>(energy_->num_labels());
  std::fill(relaxation_->logits.begin(), relaxation_->logits.end(), 0.0);
  for (std::size_t i = 0; i < labeling_.size(); ++i)
    relaxation_->logits[i * L + static_cast<std::size_t>(labeling_[i])] = kStartMargin;
  const std::vector<double> sizes =
      detail::relaxed_cooperative_cut_sizes(*energy_, options_.relaxation, relaxation_->logits);
  last_.relaxation_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const CoopAuxiliary h = CoopAuxiliary::optimal_for(*energy_, std::span<const double>(sizes));
  keep_if_lower(expand_for(h, labeling_), h);
}

}  // namespace c2f
