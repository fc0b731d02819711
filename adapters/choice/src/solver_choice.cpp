#include "c2f/adapters/solver_choice.hpp"

#include "c2f/core/enum_names.hpp"

namespace c2f {

std::string_view to_string(SolverKind kind) {
  switch (kind) {
    case SolverKind::expansion:
      return "expansion";
    case SolverKind::swap:
      return "swap";
    case SolverKind::lbp:
      return "lbp";
    case SolverKind::icm:
      return "icm";
  }
  return "unknown";
}

SolverKind solver_kind_from_string(std::string_view text) {
  constexpr SolverKind kAll[] = {SolverKind::expansion, SolverKind::swap, SolverKind::lbp,
                                 SolverKind::icm};
  return enum_from_string(text, kAll, "solver");
}

std::string_view to_string(MaxFlowKind kind) {
  switch (kind) {
    case MaxFlowKind::dynamic:
      return "dynamic";
    case MaxFlowKind::boost:
      return "boost";
    case MaxFlowKind::kolmogorov:
      return "kolmogorov";
  }
  return "unknown";
}

MaxFlowKind maxflow_kind_from_string(std::string_view text) {
  constexpr MaxFlowKind kAll[] = {MaxFlowKind::dynamic, MaxFlowKind::boost,
                                  MaxFlowKind::kolmogorov};
  return enum_from_string(text, kAll, "max-flow backend");
}

std::string_view to_string(NearLevels levels) {
  switch (levels) {
    case NearLevels::original:
      return "original";
    case NearLevels::all:
      return "all";
  }
  return "unknown";
}

NearLevels near_levels_from_string(std::string_view text) {
  constexpr NearLevels kAll[] = {NearLevels::original, NearLevels::all};
  return enum_from_string(text, kAll, "near-move levels");
}

std::string SolverChoice::validate() const {
  if (kind == SolverKind::lbp && order != VisitOrder::sequential) {
    return "lbp visits every message in every step; the order '" + std::string(to_string(order)) +
           "' applies to expansion, swap and icm";
  }
  if (kind == SolverKind::icm && order == VisitOrder::frequency) {
    return "the order 'frequency' orders labels (expansion, swap); icm visits variables";
  }
  if (near_radius != 0 && kind != SolverKind::expansion)
    return "near moves are expansion moves; solver '" + std::string(to_string(kind)) + "' has none";
  if (shift_moves && kind != SolverKind::expansion)
    return "shift moves are made by expansion; solver '" + std::string(to_string(kind)) +
           "' has none";
  if (kind == SolverKind::expansion) return expansion_options().validate();
  if (kind == SolverKind::swap) return swap_options().validate();
  return {};
}

}  // namespace c2f
