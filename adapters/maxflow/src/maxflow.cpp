#include "c2f/adapters/maxflow/maxflow.hpp"

#include <cmath>
#include <stdexcept>

namespace c2f {

void FlowCapacities::resize(std::size_t num_nodes, std::size_t num_edges) {
  source.resize(num_nodes);
  sink.resize(num_nodes);
  forward.resize(num_edges);
  backward.resize(num_edges);
}

std::string check_capacities(const FlowCapacities& caps, std::size_t num_nodes,
                             std::size_t num_edges) {
  if (caps.source.size() != num_nodes || caps.sink.size() != num_nodes) {
    return "terminal capacities have " + std::to_string(caps.source.size()) + "/" +
           std::to_string(caps.sink.size()) + " entries, the graph has " +
           std::to_string(num_nodes) + " nodes";
  }
  if (caps.forward.size() != num_edges || caps.backward.size() != num_edges) {
    return "edge capacities have " + std::to_string(caps.forward.size()) + "/" +
           std::to_string(caps.backward.size()) + " entries, the graph has " +
           std::to_string(num_edges) + " edges";
  }
  auto check = [](std::span<const double> values, const char* name) -> std::string {
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!std::isfinite(values[i]) || values[i] < 0.0) {
        return std::string(name) + "[" + std::to_string(i) + "] = " + std::to_string(values[i]) +
               " is not a finite capacity >= 0";
      }
    }
    return {};
  };
  for (auto [values, name] : {std::pair{std::span<const double>(caps.source), "source"},
                              std::pair{std::span<const double>(caps.sink), "sink"},
                              std::pair{std::span<const double>(caps.forward), "forward"},
                              std::pair{std::span<const double>(caps.backward), "backward"}}) {
    if (std::string problem = check(values, name); !problem.empty()) return problem;
  }
  return {};
}

double cut_capacity(const FlowCapacities& caps, std::span<const FlowEdge> edges,
                    std::span<const char> in_source) {
  double total = 0.0;
  for (std::size_t i = 0; i < in_source.size(); ++i)
    total += in_source[i] ? caps.sink[i] : caps.source[i];
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const bool from_s = in_source[edges[e].from];
    const bool to_s = in_source[edges[e].to];
    if (from_s && !to_s) total += caps.forward[e];
    if (!from_s && to_s) total += caps.backward[e];
  }
  return total;
}

void check_topology(std::size_t num_nodes, std::span<const FlowEdge> edges, const char* who) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edges[e].from >= num_nodes || edges[e].to >= num_nodes || edges[e].from == edges[e].to) {
      throw std::invalid_argument(std::string(who) + ": edge " + std::to_string(e) + " (" +
                                  std::to_string(edges[e].from) + ", " +
                                  std::to_string(edges[e].to) +
                                  ") must join two different nodes < " + std::to_string(num_nodes));
    }
  }
}

}  // namespace c2f
