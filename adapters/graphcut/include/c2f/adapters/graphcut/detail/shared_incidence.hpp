#pragma once
// Internal to ExpansionSolver: one EdgeIncidence per binding for every part of the solver that
// walks an energy's edges by variable (kept move problems, near moves, region moves). Installed
// only because the solver templates include it.

#include <memory>

#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f::detail {

/// The edge incidences of one energy, built the first time a part asks for them and shared by
/// every part that asks (each keeps its own reference).
class SharedIncidence {
 public:
  explicit SharedIncidence(const PairwiseEnergy& energy) : energy_(&energy) {}

  [[nodiscard]] std::shared_ptr<const EdgeIncidence> get() {
    if (!built_) built_ = std::make_shared<const EdgeIncidence>(*energy_);
    return built_;
  }

 private:
  const PairwiseEnergy* energy_;
  std::shared_ptr<const EdgeIncidence> built_;
};

/// `shared`'s incidences, or incidences of the energy's own when there is none.
[[nodiscard]] inline std::shared_ptr<const EdgeIncidence> incidence_of(const PairwiseEnergy& energy,
                                                                       SharedIncidence* shared) {
  return shared != nullptr ? shared->get() : std::make_shared<const EdgeIncidence>(energy);
}

}  // namespace c2f::detail
