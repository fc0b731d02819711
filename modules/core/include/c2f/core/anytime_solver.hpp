#pragma once
// The AnytimeSolver concept: a solver that improves a labeling in small units of work.

#include <concepts>
#include <cstddef>
#include <span>

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

}  // namespace c2f
