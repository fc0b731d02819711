#include "c2f/lift/aggregated_best_labels.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "c2f/core/edge_incidence.hpp"

namespace c2f {

namespace {

/// Row y's horizontal window sums, label-minor: out[x * L + l] = sum over x' in
/// [x - radius, x + radius] (clipped) of unary(y * width + x', l). O(width * L) whatever the
/// radius: differences of prefix sums (`prefix` is scratch).
void row_window_sums(const LiftingView& view, GridShape shape, std::size_t y, std::size_t radius,
                     std::vector<double>& prefix, std::vector<double>& out) {
  const std::size_t w = shape.width;
  const auto L = static_cast<std::size_t>(view.num_labels);
  prefix.assign((w + 1) * L, 0.0);
  view.unaries.visit([&](auto costs) {
    const auto row = costs.subspan(y * w * L, w * L);
    for (std::size_t x = 0; x < w; ++x)
      for (std::size_t l = 0; l < L; ++l)
        prefix[(x + 1) * L + l] = prefix[x * L + l] + static_cast<double>(row[x * L + l]);
  });
  out.resize(w * L);
  for (std::size_t x = 0; x < w; ++x) {
    const std::size_t first = x >= radius ? x - radius : 0;
    const std::size_t end = std::min(w, x + 1 + std::min(radius, w));
    for (std::size_t l = 0; l < L; ++l)
      out[x * L + l] = prefix[end * L + l] - prefix[first * L + l];
  }
}

}  // namespace

DensePartition aggregated_best_labels(const LiftingView& view, GridShape shape, int radius) {
  require_grid_size(view.num_variables, shape, "aggregated_best_labels");
  if (radius < 0) throw std::invalid_argument("aggregated_best_labels: radius must be >= 0");
  const std::size_t w = shape.width, h = shape.height;
  const auto L = static_cast<std::size_t>(view.num_labels);
  const auto r = static_cast<std::size_t>(radius);
  // The window's sums slide down the grid: a row's horizontal sums are added as the row enters
  // the window and computed again and subtracted as it leaves.
  std::vector<double> window(w * L, 0.0), sums, prefix;
  std::vector<std::int64_t> best(shape.size());
  std::size_t entered = 0, left = 0;  // rows [left, entered) are in the window
  for (std::size_t y = 0; y < h; ++y) {
    const std::size_t first = y >= r ? y - r : 0;
    const std::size_t end = std::min(h, y + 1 + std::min(r, h));
    for (; entered < end; ++entered) {
      row_window_sums(view, shape, entered, r, prefix, sums);
      for (std::size_t k = 0; k < window.size(); ++k) window[k] += sums[k];
    }
    for (; left < first; ++left) {
      row_window_sums(view, shape, left, r, prefix, sums);
      for (std::size_t k = 0; k < window.size(); ++k) window[k] -= sums[k];
    }
    for (std::size_t x = 0; x < w; ++x) {
      const double* costs = window.data() + x * L;
      best[y * w + x] = std::min_element(costs, costs + L) - costs;  // ties: the smallest label
    }
  }
  return DensePartition::from_ids(best);
}

DensePartition aggregated_best_labels(const LiftingView& view, int radius) {
  if (radius < 0) throw std::invalid_argument("aggregated_best_labels: radius must be >= 0");
  const std::size_t n = view.num_variables;
  const auto L = static_cast<std::size_t>(view.num_labels);
  const EdgeIncidence neighbours(n, std::span<const ColourFactor>(view.factors));
  std::vector<std::int64_t> best(n);
  view.unaries.visit([&](auto unary) {
    // Rounds 1 .. radius - 1 are kept whole (the next round reads every neighbour's); the last
    // round is summed per variable and only its least label kept.
    using Cost = std::remove_const_t<typename decltype(unary)::element_type>;
    std::vector<Cost> current, next;
    const auto sum_round = [&](auto previous, std::size_t v, double* out) {
      for (std::size_t l = 0; l < L; ++l) out[l] = static_cast<double>(previous[v * L + l]);
      for (const Incidence& incidence : neighbours.of(v)) {
        const std::size_t u = incidence.other;
        for (std::size_t l = 0; l < L; ++l) out[l] += static_cast<double>(previous[u * L + l]);
      }
    };
    std::vector<double> sums(L);
    for (int round = 1; round < radius; ++round) {
      next.resize(n * L);
      for (std::size_t v = 0; v < n; ++v) {
        if (round == 1)
          sum_round(unary, v, sums.data());
        else
          sum_round(std::span<const Cost>(current), v, sums.data());
        for (std::size_t l = 0; l < L; ++l) next[v * L + l] = static_cast<Cost>(sums[l]);
      }
      current.swap(next);
    }
    for (std::size_t v = 0; v < n; ++v) {
      if (radius == 0) {
        for (std::size_t l = 0; l < L; ++l) sums[l] = static_cast<double>(unary[v * L + l]);
      } else if (radius == 1) {
        sum_round(unary, v, sums.data());
      } else {
        sum_round(std::span<const Cost>(current), v, sums.data());
      }
      best[v] = std::min_element(sums.begin(), sums.end()) - sums.begin();  // ties: smallest
    }
  });
  return DensePartition::from_ids(best);
}

}  // namespace c2f
