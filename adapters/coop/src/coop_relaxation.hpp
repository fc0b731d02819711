#pragma once
// Internal to CoopSolver's ceres strategy: the continuous relaxation of a cooperative cut,
// solved with Ceres' GradientProblemSolver (L-BFGS).

#include <vector>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/cooperative/coop_energy.hpp"

namespace c2f::detail {

/// Minimises the relaxed energy over logits z (pixels x labels, row-major), p = softmax per
/// pixel:
///   f(z) = sum p phi + lambda [ sum_{l, g < K} F~_g(S~_lg) + sum_l S~_lK ]
///   S~_lg = sum_e sum_{(g, w) on u's side} w/2 p_ul (1 - p_vl) + (v's side) w/2 p_vl (1 - p_ul)
/// where F~_g is the soft minimum of F_g's two branches (temperature options.smoothing times
/// the breakpoint), starting from `logits` and leaving the solution there (at most
/// options.max_iterations iterations). Returns the relaxed cut sizes of the cooperative
/// classes at the solution, S~_lg for g < K, row-major l * K + g (what
/// CoopAuxiliary::optimal_for reads). Ceres' glog warnings are silenced (errors still show).
std::vector<double> relaxed_cooperative_cut_sizes(const CoopEnergy& energy,
                                                  const RelaxationOptions& options,
                                                  std::vector<double>& logits);

}  // namespace c2f::detail
