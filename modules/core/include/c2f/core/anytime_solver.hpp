#pragma once
// The AnytimeSolver concept: a solver that improves a labeling in small units of work.

#include <concepts>
#include <cstddef>
#include <span>
#include <type_traits>

#include "c2f/core/energy.hpp"
#include "c2f/core/labeling.hpp"

namespace c2f {

/// What every shipped solver's `last_step()` reports about its last step (solvers extend it
/// with what is particular to them: the label of an expansion move, the message change of BP).
struct StepOutcome {
  std::size_t changed = 0;  ///< variables whose label the step changed (0 unless improved)
  bool improved = false;    ///< the step lowered the energy
};

/// A solver S that minimises energies of type E one unit of work at a time.
/// Contract:
///  - `bind(e, x)` starts from labeling x of e (validated; throws std::invalid_argument when
///    it is not a labeling of e). e must outlive the binding. Rebinding to another energy of
///    the same type (another level) is allowed at any time.
///  - `step()` does one unit of work (one expansion move, one BP iteration, one sweep) and
///    returns the energy of the current labeling. The returned energy never increases across
///    steps of one binding.
///  - `energy()` and `labeling()` report the current (best) labeling and its energy.
template <class S, class E>
concept AnytimeSolver = Energy<E> &&
    requires(S& s, const S& cs, const E& e, std::span<const Label> x) {
  s.bind(e, x);
  { s.step() } -> std::convertible_to<double>;
  { cs.energy() } -> std::convertible_to<double>;
  { cs.labeling() } -> std::convertible_to<std::span<const Label>>;
};

/// An AnytimeSolver that says when it has converged: after quiet_steps_to_converge(e)
/// consecutive steps without a decrease on energy e, no step of its kind lowers the energy
/// (one sweep of its moves; a fixed point). The driver ends the original problem there unless
/// told otherwise (Options::plateau_steps_at_original), so default options converge.
template <class S, class E>
concept ConvergingSolver = AnytimeSolver<S, E> && requires(const S& cs, const E& e) {
  { cs.quiet_steps_to_converge(e) } -> std::convertible_to<std::size_t>;
};

/// A solver that says how many variables its last step worked over (a graph-cut solver's
/// last_step().variables: the level's for a whole move, fewer for a near move). The driver
/// reports it with each step (StepEvent::step_variables); for any other solver a step counts
/// every variable of its level.
template <class S>
concept StepScopeSolver = requires(const S& cs) {
  { cs.last_step().variables } -> std::convertible_to<std::size_t>;
};

/// A solver that can give back the memory it keeps between steps (recycled move graphs, kept
/// move problems): release() leaves it as newly constructed with its options, to be bound
/// again. The driver calls it on the coarse levels' solver as the original problem begins, so
/// their memory is not held beside the original problem's.
template <class S>
concept ReleasingSolver = requires(S& s) { s.release(); };

/// Two solvers for one coarse-to-fine run: `coarse` on every reduced level, `original` on the
/// original problem (e.g. whole expansion moves on the coarse levels and near moves on the
/// original one). Holds references: both must outlive the run. They may be one object.
template <class CoarseSolver, class OriginalSolver>
struct LevelSolvers {
  LevelSolvers(CoarseSolver& coarse_solver, OriginalSolver& original_solver)
      : coarse(coarse_solver), original(original_solver) {}
  CoarseSolver& coarse;
  OriginalSolver& original;
};

namespace detail {
template <class S>
inline constexpr bool is_level_solvers = false;
template <class C, class O>
inline constexpr bool is_level_solvers<LevelSolvers<C, O>> = true;
}  // namespace detail

/// What coarse_to_fine accepts as its solvers for energies of type E (references and const
/// aside): one AnytimeSolver for every level, or LevelSolvers of two.
template <class S, class E>
concept SolversFor = AnytimeSolver<std::remove_cvref_t<S>, E> ||
    (detail::is_level_solvers<std::remove_cvref_t<S>>&& requires(std::remove_cvref_t<S>& s) {
      requires AnytimeSolver<std::remove_cvref_t<decltype(s.coarse)>, E>;
      requires AnytimeSolver<std::remove_cvref_t<decltype(s.original)>, E>;
    });

}  // namespace c2f
