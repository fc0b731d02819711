#pragma once
// Colour passing (Kersting et al. 2009) adapted to vision energies as in the paper's section
// 3.3: CP(N_L, N_iter), the partition after N_iter colour-passing iterations with unary split
// threshold N_L.
//
// Factor graph: one unary factor per variable and one pairwise factor per edge, connected to
// BOTH endpoints (the reference implementation connected only the first endpoint; see
// local_grouping for what it computed). Initial colours: all variables one colour; a unary
// factor's colour is the ordered tuple of its N_L lowest-cost labels (ties broken by label
// index); a pairwise factor's colour is what the energy's LiftingView gives it (for a pairwise
// energy its (term, weight)). One iteration: every pairwise
// factor takes the colour of its signature (own colour, endpoint colours: sorted for
// symmetric terms, in order for asymmetric ones), then every variable takes the colour of
// (own colour, own unary factor's colour, multiset of its pairwise factors' colours, with the
// endpoint position for asymmetric terms). Signatures are compared exactly, so two different
// signatures never share a colour. Increasing N_L splits every variable (and unary factor)
// colour by the N_L-th lowest-cost label. Both operations refine the partition.

#include <cstdint>
#include <span>
#include <vector>

#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/lifting_view.hpp"

namespace c2f {

/// The `count` lowest-cost labels of `row` in increasing cost order, ties broken by the lower
/// label. Requires 1 <= count <= row.size().
void lowest_cost_labels(UnaryRow row, std::size_t count, std::span<Label> out);

class ColourPassing {
 public:
  /// The state CP(labels, 0) of a model: every variable in one group. The view's unaries must
  /// outlive this object (its factors are copied). Throws std::invalid_argument unless
  /// 1 <= labels <= num_labels.
  ColourPassing(const LiftingView& view, int labels);
  /// The same for a pairwise energy (lifting_view(energy)); the energy must outlive this object.
  ColourPassing(const PairwiseEnergy& energy, int labels);

  /// One colour-passing iteration (N_iter + 1). Returns true when the variable partition
  /// became finer.
  bool iterate();
  /// N_L + 1: splits every group by the members' N_L-th lowest-cost label. Throws
  /// std::logic_error when N_L already equals the number of labels.
  void increase_labels();

  [[nodiscard]] int labels() const noexcept { return labels_; }
  [[nodiscard]] int iterations() const noexcept { return iterations_; }
  [[nodiscard]] std::size_t num_groups() const noexcept { return num_variable_colours_; }
  /// The current partition CP(labels(), iterations()).
  [[nodiscard]] DensePartition partition() const;

 private:
  UnaryCosts unaries_;
  int num_labels_;
  LargeVector<ColourFactor> factors_;
  int labels_;
  int iterations_ = 0;
  std::vector<std::uint32_t> variable_colour_;
  std::size_t num_variable_colours_ = 1;
  std::vector<std::uint32_t> unary_colour_;
  std::vector<std::uint32_t> pair_colour_;
  std::vector<char> pair_symmetric_;
  std::vector<Label> last_label_;  // the labels_-th lowest-cost label of every variable
  std::vector<double> last_cost_;  // and its cost, for finding the next one
  EdgeIncidence incidence_;
};

}  // namespace c2f
