#pragma once
// Aggregated best labels: pixels whose unary costs, summed over a window around them, are
// cheapest at the same label share a group. The sum smooths the per-pixel best labels (noisy
// where the unaries are, as stereo matching costs are), so with /cc the groups are far fewer
// and larger regions than those of equal per-pixel best labels (local:1,1/cc). On an energy
// that is no pixel grid the sum runs over graph neighbourhoods instead of windows.

#include <cstdint>
#include <vector>

#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/grid.hpp"
#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/lifting_view.hpp"

namespace c2f {

/// Pixel v = y * width + x of the width x height grid is in group l when l is the label with
/// the least sum of unary costs over the pixels of the (2 radius + 1) x (2 radius + 1) window
/// centred on v, clipped at the grid's border (ties: the smallest label). Groups are numbered
/// in the order of their smallest pixel; they need not be connected (add /cc in a schedule, or
/// connected_components()). radius 0: pixels share a group when their own cheapest labels are
/// equal. O(N * L) time whatever the radius, O(width * L) extra memory (17 rows' worth): the
/// sums slide down the grid, so they are exact up to rounding, and rounding may break
/// near-ties. The rows' sums and the columns are split among up to `threads` threads (0: the
/// machine's cores), with the same bits for every count. Throws std::invalid_argument when the
/// view does not have width * height variables or radius < 0.
DensePartition aggregated_best_labels(const LiftingView& view, GridShape shape, int radius,
                                      int threads = 1);

/// The same on the graph of the view's factors, for an energy that is no pixel grid: the costs
/// are summed `radius` times over graph neighbourhoods, s_0 = unary and s_{k+1}(v) = s_k(v) +
/// sum of s_k(u) over the factors {u, v} (a factor listed twice counts twice), and v is in group
/// l when l is the least of s_radius(v) (ties: the smallest label). Groups are numbered in the
/// order of their smallest variable and need not be connected (connected_components_along_edges
/// splits them). On a 4-connected grid, radius 1 sums the pixel and its four neighbours.
/// O(radius * (N + F) * L) time; extra memory: the neighbour lists, O(N + F), and for radius
/// >= 2 one table of N * L sums in the unaries' precision (two from radius 3). Each variable's
/// sums are its own, so the variables are split among up to `threads` threads (0: the
/// machine's cores) with the same result for every count. Throws std::invalid_argument when
/// radius < 0.
DensePartition aggregated_best_labels(const LiftingView& view, int radius, int threads = 1);

/// aggregated_best_labels(view, radius) off a grid for one radius after another (agg:R,MAX,SHARE
/// widening), each round of sums made once across the calls: the same partitions, bits
/// included, for the cost of the widest radius asked. The view must outlive this object.
class GraphAggregation {
 public:
  /// Builds the neighbour lists of the view's factors, O(N + F).
  explicit GraphAggregation(const LiftingView& view, int threads = 1);

  /// aggregated_best_labels(view, radius, threads). With keep, the sums of this radius are
  /// kept (a table of N * L in the unaries' precision) so that a wider radius goes on from
  /// them. Throws std::invalid_argument when radius < 0, or when radius > 0 and radius - 1 is
  /// below the radius whose sums are kept (those of a radius asked before with keep).
  DensePartition best_labels(int radius, bool keep = false);

 private:
  /// s_{kept_ + 1} from s_{kept_}; with best, each variable's least label of it too. Keeps it
  /// when `keep`.
  void next_round(std::vector<std::int64_t>* best, bool keep);

  const LiftingView* view_;
  EdgeIncidence neighbours_;
  int threads_;
  int kept_ = 0;  ///< the round the kept sums hold (0: the unaries themselves)
  std::vector<float> float_sums_, next_float_;     ///< with float unaries
  std::vector<double> double_sums_, next_double_;  ///< with double unaries
};

}  // namespace c2f
