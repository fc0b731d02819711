#include "c2f/lift/aggregated_best_labels.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace c2f {

namespace {

/// Row y's horizontal window sums, label-minor: out[x * L + l] = sum over x' in
/// [x - radius, x + radius] (clipped) of unary(y * width + x', l).
void row_window_sums(const LiftingView& view, GridShape shape, std::size_t y, std::size_t radius,
                     std::vector<double>& out) {
  const std::size_t w = shape.width;
  const auto L = static_cast<std::size_t>(view.num_labels);
  const double* row = view.unaries.data() + y * w * L;
  out.assign(w * L, 0.0);
  for (std::size_t x = 0; x < w; ++x) {
    const std::size_t first = x >= radius ? x - radius : 0;
    const std::size_t last = std::min(w - 1, x + radius);
    double* sums = out.data() + x * L;
    for (std::size_t x2 = first; x2 <= last; ++x2) {
      const double* costs = row + x2 * L;
      for (std::size_t l = 0; l < L; ++l) sums[l] += costs[l];
    }
  }
}

}  // namespace

DensePartition aggregated_best_labels(const LiftingView& view, GridShape shape, int radius) {
  require_grid_size(view.num_variables, shape, "aggregated_best_labels");
  if (radius < 0) throw std::invalid_argument("aggregated_best_labels: radius must be >= 0");
  const std::size_t w = shape.width, h = shape.height;
  const auto L = static_cast<std::size_t>(view.num_labels);
  const auto r = static_cast<std::size_t>(radius);
  // The window's rows' horizontal sums, kept for rows y - r .. y + r in a ring of 2r + 1 rows.
  const std::size_t ring_rows = std::min(h, 2 * r + 1);
  std::vector<std::vector<double>> ring(ring_rows);
  std::vector<double> window(w * L);
  std::vector<std::int64_t> best(shape.size());
  std::size_t next_row = 0;  // the next row whose sums enter the ring
  for (std::size_t y = 0; y < h; ++y) {
    const std::size_t first = y >= r ? y - r : 0;
    const std::size_t last = std::min(h - 1, y + r);
    for (; next_row <= last; ++next_row)
      row_window_sums(view, shape, next_row, r, ring[next_row % ring_rows]);
    // Summed row by row in a fixed order, so equal windows give equal sums.
    std::fill(window.begin(), window.end(), 0.0);
    for (std::size_t y2 = first; y2 <= last; ++y2) {
      const std::vector<double>& sums = ring[y2 % ring_rows];
      for (std::size_t k = 0; k < window.size(); ++k) window[k] += sums[k];
    }
    for (std::size_t x = 0; x < w; ++x) {
      const double* sums = window.data() + x * L;
      std::size_t label = 0;
      for (std::size_t l = 1; l < L; ++l)
        if (sums[l] < sums[label]) label = l;
      best[y * w + x] = static_cast<std::int64_t>(label);
    }
  }
  return DensePartition::from_ids(best);
}

}  // namespace c2f
