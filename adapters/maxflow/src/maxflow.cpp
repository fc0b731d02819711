#include "c2f/adapters/maxflow/maxflow.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "c2f/support/parallel_for.hpp"

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

namespace {

[[nodiscard]] bool joins_two_nodes(const FlowEdge& edge, std::size_t num_nodes) noexcept {
  return edge.from < num_nodes && edge.to < num_nodes && edge.from != edge.to;
}

/// Edges per task of check_topology's parallel pass.
constexpr std::size_t kCheckChunk = 65536;

}  // namespace

void check_topology(std::size_t num_nodes, std::span<const FlowEdge> edges, const char* who,
                    int threads) {
  if (threads != 1 && edges.size() > kCheckChunk) {
    std::vector<std::uint8_t> fine((edges.size() + kCheckChunk - 1) / kCheckChunk);
    parallel_for_chunks(
        edges.size(), kCheckChunk,
        [&](std::size_t c, std::size_t first, std::size_t last) {
          bool ok = true;
          for (std::size_t e = first; e < last; ++e) ok &= joins_two_nodes(edges[e], num_nodes);
          fine[c] = ok ? 1 : 0;
        },
        threads);
    if (std::all_of(fine.begin(), fine.end(), [](std::uint8_t f) { return f != 0; })) return;
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!joins_two_nodes(edges[e], num_nodes)) {
      throw std::invalid_argument(std::string(who) + ": edge " + std::to_string(e) + " (" +
                                  std::to_string(edges[e].from) + ", " +
                                  std::to_string(edges[e].to) +
                                  ") must join two different nodes < " + std::to_string(num_nodes));
    }
  }
}

}  // namespace c2f
