#pragma once
// The exact energy of a labeling kept as partial sums over PairwiseEnergy's evaluation chunks,
// so that a labeling differing from it in a few variables is evaluated in proportion to the
// chunks those variables touch, to the same bits as PairwiseEnergy::evaluate_unchecked (which
// sums over the same chunks). What a move-making solver needs to check each move's exact
// energy without an O(N + E) pass per move.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

class EnergyTally {
 public:
  /// Tallies `labeling` (a valid labeling of `energy`, which must outlive the tally) using the
  /// edge incidences `incidence` of the same energy. Chunks are summed on up to `threads`
  /// threads (0: the machine's cores) when there are enough of them; the sums never depend on
  /// the thread count. O(N + E).
  void bind(const PairwiseEnergy& energy, std::span<const Label> labeling,
            std::shared_ptr<const EdgeIncidence> incidence, int threads);

  /// Whether bind() was called.
  [[nodiscard]] bool bound() const noexcept { return energy_ != nullptr; }
  /// The tallied labeling's energy: bitwise energy.evaluate_unchecked(labeling).
  [[nodiscard]] double value() const noexcept { return value_; }

  /// The energy of `candidate`, which may differ from the tallied labeling only in the
  /// variables `changed` lists (in any order, repeats allowed): bitwise
  /// energy.evaluate_unchecked(candidate). Recomputes only the chunks of those variables and of
  /// their edges. The tallied labeling stays until keep().
  [[nodiscard]] double evaluate_changed(std::span<const Label> candidate,
                                        std::span<const VariableIndex> changed);
  /// Makes the candidate last given to evaluate_changed() the tallied labeling.
  void keep();

 private:
  void sum_chunks(std::span<const Label> x, std::span<const std::uint32_t> unary_chunks,
                  std::span<const std::uint32_t> pairwise_chunks);

  const PairwiseEnergy* energy_ = nullptr;
  std::shared_ptr<const EdgeIncidence> incidence_;
  int threads_ = 1;
  // Per chunk: the tallied labeling's sums, the last candidate's, and whether a chunk is
  // in the candidate's lists of touched chunks.
  std::vector<double> unary_, pairwise_, candidate_unary_, candidate_pairwise_;
  std::vector<std::uint8_t> unary_touched_, pairwise_touched_;
  std::vector<std::uint32_t> touched_unary_, touched_pairwise_;
  double value_ = 0.0;
  double candidate_value_ = 0.0;
};

}  // namespace c2f
