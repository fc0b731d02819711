#pragma once
// Optional max-flow backend on Kolmogorov's maxflow library (Debian libmaxflow-dev, GPL-3).
// Only available when c2f is configured with C2F_WITH_KOLMOGOROV_MAXFLOW=ON.

#include <cstddef>
#include <memory>
#include <span>

#include "c2f/adapters/maxflow/maxflow.hpp"

namespace c2f {

/// Boykov-Kolmogorov max-flow as implemented by Kolmogorov (maxflow 3.0, double capacities).
/// solve() resets the library's graph (its memory is kept, so nothing is allocated) and
/// re-adds nodes and arcs with the new capacities.
class KolmogorovMaxFlow {
 public:
  KolmogorovMaxFlow();
  ~KolmogorovMaxFlow();
  KolmogorovMaxFlow(KolmogorovMaxFlow&&) noexcept;
  KolmogorovMaxFlow& operator=(KolmogorovMaxFlow&&) noexcept;

  void build(std::size_t num_nodes, std::span<const FlowEdge> edges);
  double solve(const FlowCapacities& caps);
  [[nodiscard]] bool in_source_set(FlowNode node) const;
  [[nodiscard]] std::size_t num_nodes() const noexcept;
  [[nodiscard]] std::size_t num_edges() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

static_assert(MaxFlow<KolmogorovMaxFlow>);

}  // namespace c2f
