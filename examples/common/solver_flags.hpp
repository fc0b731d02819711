#pragma once
// The options that choose a solver, shared by the tools that offer every solver (c2f-stereo,
// c2f-solve): --solver, --maxflow, --graph-memory and --label-order.

#include <string>

#include "c2f/adapters/solver_choice.hpp"
#include "tool_options.hpp"

namespace c2f::examples {

class SolverFlags {
 public:
  /// Declares the four options in `options` (this object receives their values, so it must
  /// outlive options.parse()).
  void declare(ToolOptions& options);

  /// The solver the parsed options choose. Throws std::invalid_argument naming the option for
  /// an unknown name, a visit order the solver does not take, or a backend not in this build.
  [[nodiscard]] SolverChoice choice() const;

 private:
  std::string solver_ = "expansion", label_order_ = "sequential", maxflow_ = "dynamic";
  double graph_memory_gib_ = static_cast<double>(MoveOptions{}.graph_memory_limit) / (1 << 30);
};

}  // namespace c2f::examples
