#include "c2f/adapters/maxflow/kolmogorov_maxflow.hpp"

#include <maxflow.h>

#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace c2f {

struct KolmogorovMaxFlow::Impl {
  using Graph = maxflow::Graph<double, double, double>;
  std::size_t num_nodes = 0;
  std::vector<FlowEdge> edges;
  std::optional<Graph> graph;
};

KolmogorovMaxFlow::KolmogorovMaxFlow() : impl_(std::make_unique<Impl>()) {}
KolmogorovMaxFlow::~KolmogorovMaxFlow() = default;
KolmogorovMaxFlow::KolmogorovMaxFlow(KolmogorovMaxFlow&&) noexcept = default;
KolmogorovMaxFlow& KolmogorovMaxFlow::operator=(KolmogorovMaxFlow&&) noexcept = default;

void KolmogorovMaxFlow::build(std::size_t num_nodes, std::span<const FlowEdge> edges) {
  check_topology(num_nodes, edges, "KolmogorovMaxFlow::build");
  if (num_nodes > static_cast<std::size_t>(std::numeric_limits<int>::max() / 2) ||
      edges.size() > static_cast<std::size_t>(std::numeric_limits<int>::max() / 4)) {
    throw std::invalid_argument(
        "KolmogorovMaxFlow::build: graph too large for the library's int ids");
  }
  Impl& m = *impl_;
  m.num_nodes = num_nodes;
  m.edges.assign(edges.begin(), edges.end());
  m.graph.emplace(static_cast<int>(std::max<std::size_t>(num_nodes, 1)),
                  static_cast<int>(std::max<std::size_t>(edges.size(), 1)));
}

double KolmogorovMaxFlow::solve(const FlowCapacities& caps) {
  Impl& m = *impl_;
  if (!m.graph) throw std::logic_error("KolmogorovMaxFlow::solve: call build() first");
  if (caps.source.size() != m.num_nodes || caps.sink.size() != m.num_nodes ||
      caps.forward.size() != m.edges.size() || caps.backward.size() != m.edges.size()) {
    throw std::invalid_argument("KolmogorovMaxFlow::solve: " +
                                check_capacities(caps, m.num_nodes, m.edges.size()));
  }
  Impl::Graph& g = *m.graph;
  g.reset();
  if (m.num_nodes == 0) return 0.0;
  g.add_node(static_cast<int>(m.num_nodes));
  for (std::size_t i = 0; i < m.num_nodes; ++i) {
    g.add_tweights(static_cast<int>(i), caps.source[i], caps.sink[i]);
  }
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    g.add_edge(static_cast<int>(m.edges[e].from), static_cast<int>(m.edges[e].to), caps.forward[e],
               caps.backward[e]);
  }
  return g.maxflow();
}

bool KolmogorovMaxFlow::in_source_set(FlowNode node) const {
  // Nodes in neither search tree are reported as SOURCE by the library: also a minimum cut.
  return impl_->graph->what_segment(static_cast<int>(node)) == Impl::Graph::SOURCE;
}

std::size_t KolmogorovMaxFlow::num_nodes() const noexcept {
  return impl_->num_nodes;
}
std::size_t KolmogorovMaxFlow::num_edges() const noexcept {
  return impl_->edges.size();
}

}  // namespace c2f
