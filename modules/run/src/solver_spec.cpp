#include "c2f/run/solver_spec.hpp"

#include "c2f/support/enum_names.hpp"

namespace c2f {

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

SolverKind solver_kind(const SolverOptions& options) noexcept {
  return static_cast<SolverKind>(options.index());
}

SolverOptions default_solver_options(SolverKind kind) {
  switch (kind) {
    case SolverKind::expansion:
      return ExpansionOptions{};
    case SolverKind::swap:
      return SwapOptions{};
    case SolverKind::lbp:
      return LbpOptions{};
    case SolverKind::icm:
      return IcmOptions{};
  }
  throw std::invalid_argument("default_solver_options: unknown solver kind");
}

bool recycles_move_graphs(const SolverOptions& options) noexcept {
  return std::holds_alternative<ExpansionOptions>(options) ||
         std::holds_alternative<SwapOptions>(options);
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

namespace {

std::string validate_options(const SolverOptions& options) {
  return std::visit([](const auto& o) { return o.validate(); }, options);
}

}  // namespace

std::string SolverSpec::validate() const {
  if (recycles_move_graphs(original) && !maxflow_available(maxflow)) {
    return "maxflow: '" + std::string(to_string(maxflow)) +
           "' is not in this build (configure with -DC2F_WITH_KOLMOGOROV_MAXFLOW=ON)";
  }
  if (std::string problem = validate_options(original); !problem.empty())
    return "original: " + problem;
  for (const SolverOptions* options : {&original, coarse ? &*coarse : nullptr}) {
    const auto* expansion = options ? std::get_if<ExpansionOptions>(options) : nullptr;
    if (expansion && expansion->flow_parts > 1 && maxflow != MaxFlowKind::dynamic) {
      return "maxflow: flow_parts " + std::to_string(expansion->flow_parts) +
             " needs our max-flow ('dynamic'), and the run uses '" +
             std::string(to_string(maxflow)) + "'";
    }
  }
  if (!coarse) return {};
  if (coarse->index() != original.index()) {
    return "coarse: options of " + std::string(to_string(solver_kind(*coarse))) + " for a run of " +
           std::string(to_string(kind())) + " (the same solver on every level)";
  }
  if (std::string problem = validate_options(*coarse); !problem.empty())
    return "coarse: " + problem;
  return {};
}

SolverSpec expansion_spec(const ExpansionOptions& options, NearLevels levels, MaxFlowKind maxflow) {
  SolverSpec spec{maxflow, options, std::nullopt};
  if (levels == NearLevels::original) {
    ExpansionOptions whole = options;
    whole.near_radius = 0;
    whole.shift_moves = false;
    whole.shift_moves_unless_submodular = false;
    if (!(whole == options)) spec.coarse = whole;
  }
  return spec;
}

}  // namespace c2f
