#include "c2f/adapters/maxflow/boost_maxflow.hpp"

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/property_map.hpp>

#include <cassert>
#include <stdexcept>
#include <utility>
#include <vector>

namespace c2f {

namespace {
struct ArcId {
  std::uint32_t arc = 0;
};
using Graph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, ArcId,
                                                 boost::no_property, std::uint32_t, std::uint32_t>;
using EdgeDescriptor = boost::graph_traits<Graph>::edge_descriptor;
}  // namespace

struct BoostMaxFlow::Impl {
  std::size_t num_nodes = 0;
  std::size_t num_edges = 0;
  Graph graph;
  // CSR edge index of: the source->i and i->sink arcs of every node; the forward and backward
  // arcs of every edge.
  std::vector<std::uint32_t> source_arc, sink_arc, forward_arc, backward_arc;
  std::vector<double> capacity, residual;
  std::vector<EdgeDescriptor> reverse, predecessor;
  std::vector<boost::default_color_type> colour;
  std::vector<long> distance;
};

BoostMaxFlow::BoostMaxFlow() : impl_(std::make_unique<Impl>()) {}
BoostMaxFlow::~BoostMaxFlow() = default;
BoostMaxFlow::BoostMaxFlow(BoostMaxFlow&&) noexcept = default;
BoostMaxFlow& BoostMaxFlow::operator=(BoostMaxFlow&&) noexcept = default;

void BoostMaxFlow::build(std::size_t num_nodes, std::span<const FlowEdge> edges) {
  check_topology(num_nodes, edges, "BoostMaxFlow::build");
  Impl& m = *impl_;
  m.num_nodes = num_nodes;
  m.num_edges = edges.size();
  const auto source = static_cast<std::uint32_t>(num_nodes);
  const auto sink = static_cast<std::uint32_t>(num_nodes + 1);
  // Our arc numbering: node i has 4i (s->i), 4i+1 (i->s), 4i+2 (i->t), 4i+3 (t->i); edge e has
  // 4n+2e (from->to) and 4n+2e+1 (to->from). The reverse of arc a is a ^ 1.
  const std::size_t num_arcs = 4 * num_nodes + 2 * edges.size();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> arcs;
  arcs.reserve(num_arcs);
  for (std::size_t i = 0; i < num_nodes; ++i) {
    const auto node = static_cast<std::uint32_t>(i);
    arcs.emplace_back(source, node);
    arcs.emplace_back(node, source);
    arcs.emplace_back(node, sink);
    arcs.emplace_back(sink, node);
  }
  for (const FlowEdge& e : edges) {
    arcs.emplace_back(e.from, e.to);
    arcs.emplace_back(e.to, e.from);
  }
  std::vector<ArcId> ids(num_arcs);
  for (std::size_t a = 0; a < num_arcs; ++a) ids[a].arc = static_cast<std::uint32_t>(a);
  m.graph = Graph(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(), ids.begin(),
                  static_cast<std::uint32_t>(num_nodes + 2));

  std::vector<std::uint32_t> csr_of_arc(num_arcs);
  std::vector<EdgeDescriptor> descriptor(num_arcs);
  const auto edge_index = get(boost::edge_index, m.graph);
  for (auto [it, end] = boost::edges(m.graph); it != end; ++it) {
    const std::uint32_t index = get(edge_index, *it);
    csr_of_arc[m.graph[*it].arc] = index;
    descriptor[index] = *it;
  }
  m.reverse.resize(num_arcs);
  for (std::size_t a = 0; a < num_arcs; ++a)
    m.reverse[csr_of_arc[a]] = descriptor[csr_of_arc[a ^ 1]];
  m.source_arc.resize(num_nodes);
  m.sink_arc.resize(num_nodes);
  for (std::size_t i = 0; i < num_nodes; ++i) {
    m.source_arc[i] = csr_of_arc[4 * i];
    m.sink_arc[i] = csr_of_arc[4 * i + 2];
  }
  m.forward_arc.resize(edges.size());
  m.backward_arc.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    m.forward_arc[e] = csr_of_arc[4 * num_nodes + 2 * e];
    m.backward_arc[e] = csr_of_arc[4 * num_nodes + 2 * e + 1];
  }
  m.capacity.assign(num_arcs, 0.0);  // arcs into the source and out of the sink stay at 0
  m.residual.assign(num_arcs, 0.0);
  m.predecessor.resize(num_nodes + 2);
  m.colour.resize(num_nodes + 2);
  m.distance.resize(num_nodes + 2);
}

double BoostMaxFlow::solve(const FlowCapacities& caps) {
  Impl& m = *impl_;
  if (m.source_arc.size() != m.num_nodes || m.predecessor.empty()) {
    throw std::logic_error("BoostMaxFlow::solve: call build() first");
  }
  if (caps.source.size() != m.num_nodes || caps.sink.size() != m.num_nodes ||
      caps.forward.size() != m.num_edges || caps.backward.size() != m.num_edges) {
    throw std::invalid_argument("BoostMaxFlow::solve: " +
                                check_capacities(caps, m.num_nodes, m.num_edges));
  }
  assert(check_capacities(caps, m.num_nodes, m.num_edges).empty());
  for (std::size_t i = 0; i < m.num_nodes; ++i) {
    m.capacity[m.source_arc[i]] = caps.source[i];
    m.capacity[m.sink_arc[i]] = caps.sink[i];
  }
  for (std::size_t e = 0; e < m.num_edges; ++e) {
    m.capacity[m.forward_arc[e]] = caps.forward[e];
    m.capacity[m.backward_arc[e]] = caps.backward[e];
  }
  const auto edge_index = get(boost::edge_index, m.graph);
  const auto vertex_index = get(boost::vertex_index, m.graph);
  return boost::boykov_kolmogorov_max_flow(
      m.graph, boost::make_iterator_property_map(m.capacity.begin(), edge_index),
      boost::make_iterator_property_map(m.residual.begin(), edge_index),
      boost::make_iterator_property_map(m.reverse.begin(), edge_index),
      boost::make_iterator_property_map(m.predecessor.begin(), vertex_index),
      boost::make_iterator_property_map(m.colour.begin(), vertex_index),
      boost::make_iterator_property_map(m.distance.begin(), vertex_index), vertex_index,
      static_cast<std::uint32_t>(m.num_nodes), static_cast<std::uint32_t>(m.num_nodes + 1));
}

bool BoostMaxFlow::in_source_set(FlowNode node) const {
  // Black: the source search tree, i.e. reachable from the source in the residual graph.
  return impl_->colour[node] == boost::black_color;
}

std::size_t BoostMaxFlow::num_nodes() const noexcept {
  return impl_->num_nodes;
}
std::size_t BoostMaxFlow::num_edges() const noexcept {
  return impl_->num_edges;
}

}  // namespace c2f
