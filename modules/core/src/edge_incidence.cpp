#include "c2f/core/edge_incidence.hpp"

namespace c2f {

EdgeIncidence::EdgeIncidence(const PairwiseEnergy& energy)
    : offsets_(energy.num_variables() + 1, 0) {
  const auto edges = energy.edges();
  for (const Edge& e : edges) {
    ++offsets_[e.u + 1];
    ++offsets_[e.v + 1];
  }
  for (std::size_t v = 0; v + 1 < offsets_.size(); ++v) offsets_[v + 1] += offsets_[v];
  incidences_.resize(offsets_.back());
  std::vector<std::size_t> cursor(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto index = static_cast<std::uint32_t>(i);
    incidences_[cursor[edges[i].u]++] = {index, edges[i].v, true};
    incidences_[cursor[edges[i].v]++] = {index, edges[i].u, false};
  }
}

}  // namespace c2f
