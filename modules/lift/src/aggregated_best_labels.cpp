#include "c2f/lift/aggregated_best_labels.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "c2f/core/edge_incidence.hpp"
#include "c2f/support/parallel_for.hpp"

namespace c2f {

namespace {

/// Variables per task of a round of graph sums: the tasks depend on N only, and each variable's
/// sums on nothing else, so the partitions are the same for every thread count.
constexpr std::size_t kVariablesPerTask = 4096;

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

DensePartition aggregated_best_labels(const LiftingView& view, int radius, int threads) {
  if (radius < 0) throw std::invalid_argument("aggregated_best_labels: radius must be >= 0");
  return GraphAggregation(view, threads).best_labels(radius);
}

GraphAggregation::GraphAggregation(const LiftingView& view, int threads)
    : view_(&view),
      neighbours_(view.num_variables, std::span<const ColourFactor>(view.factors)),
      threads_(threads) {}

DensePartition GraphAggregation::best_labels(int radius, bool keep) {
  if (radius < 0) throw std::invalid_argument("aggregated_best_labels: radius must be >= 0");
  if (radius > 0 && radius - 1 < kept_) {
    throw std::invalid_argument("GraphAggregation::best_labels: radius " + std::to_string(radius) +
                                " goes on from the sums of radius " + std::to_string(radius - 1) +
                                ", and those kept are of radius " + std::to_string(kept_));
  }
  std::vector<std::int64_t> best(view_->num_variables);
  if (radius == 0) {
    // The unaries' own least labels (kept_ is 0: nothing to keep).
    const auto L = static_cast<std::size_t>(view_->num_labels);
    view_->unaries.visit([&](auto unary) {
      parallel_for_chunks(
          best.size(), kVariablesPerTask,
          [&](std::size_t, std::size_t first, std::size_t last) {
            for (std::size_t v = first; v < last; ++v) {
              const auto costs = unary.subspan(v * L, L);
              best[v] = std::min_element(costs.begin(), costs.end()) - costs.begin();
            }
          },
          threads_);
    });
    return DensePartition::from_ids(best);
  }
  // Rounds up to radius - 1 are kept whole (the next round reads every neighbour's); the last
  // is summed per variable and, with keep, kept too.
  while (kept_ < radius - 1) next_round(nullptr, true);
  next_round(&best, keep);
  return DensePartition::from_ids(best);
}

void GraphAggregation::next_round(std::vector<std::int64_t>* best, bool keep) {
  const std::size_t n = view_->num_variables;
  const auto L = static_cast<std::size_t>(view_->num_labels);
  view_->unaries.visit([&](auto unary) {
    using Cost = std::remove_const_t<typename decltype(unary)::element_type>;
    std::vector<Cost>& sums = [&]() -> std::vector<Cost>& {
      if constexpr (std::is_same_v<Cost, float>)
        return float_sums_;
      else
        return double_sums_;
    }();
    std::vector<Cost>& next = [&]() -> std::vector<Cost>& {
      if constexpr (std::is_same_v<Cost, float>)
        return next_float_;
      else
        return next_double_;
    }();
    const std::span<const Cost> previous =
        kept_ == 0 ? unary : std::span<const Cost>(sums.data(), sums.size());
    if (keep) next.resize(n * L);
    parallel_for_chunks(
        n, kVariablesPerTask,
        [&](std::size_t, std::size_t first, std::size_t last) {
          std::vector<double> total(L);
          for (std::size_t v = first; v < last; ++v) {
            // s_{k+1}(v) = s_k(v) + the sum of s_k(u) over v's factors, in double.
            for (std::size_t l = 0; l < L; ++l) total[l] = static_cast<double>(previous[v * L + l]);
            for (const Incidence& incidence : neighbours_.of(v)) {
              const std::size_t u = incidence.other;
              for (std::size_t l = 0; l < L; ++l)
                total[l] += static_cast<double>(previous[u * L + l]);
            }
            if (best != nullptr)  // ties: the smallest label
              (*best)[v] = std::min_element(total.begin(), total.end()) - total.begin();
            if (keep)
              for (std::size_t l = 0; l < L; ++l) next[v * L + l] = static_cast<Cost>(total[l]);
          }
        },
        threads_);
    if (keep) {
      sums.swap(next);
      ++kept_;
    }
  });
}

}  // namespace c2f
