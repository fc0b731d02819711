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

/// Rows whose horizontal window sums a grid's sliding window holds at once (they are summed at
/// once, one row per task), and columns per task as the window slides over them.
constexpr std::size_t kRowsPerBatch = 8;
constexpr std::size_t kColumnsPerTask = 64;

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

DensePartition aggregated_best_labels(const LiftingView& view, GridShape shape, int radius,
                                      int threads) {
  require_grid_size(view.num_variables, shape, "aggregated_best_labels");
  if (radius < 0) throw std::invalid_argument("aggregated_best_labels: radius must be >= 0");
  const std::size_t w = shape.width, h = shape.height;
  const auto L = static_cast<std::size_t>(view.num_labels);
  const auto r = static_cast<std::size_t>(radius);
  // The window's sums slide down the grid: a row's horizontal sums are added as the row enters
  // the window and computed again and subtracted as it leaves, and each row of the grid takes
  // its least labels once the window is at it. Those steps are queued in order and run by
  // batches: the horizontal sums of a batch's rows at once, one row per task, then every step of
  // the batch on each chunk of columns at once. Each column's sums see the same additions and
  // subtractions in the same order as one thread sliding alone, so the bits do not depend on
  // the threads.
  struct SlideStep {
    enum class Kind { enter, leave, best } kind;
    std::size_t row;   // the row entering or leaving, or the row taking its least labels
    std::size_t slot;  // enter, leave: where the row's horizontal sums are
  };
  std::vector<SlideStep> batch;
  std::vector<std::size_t> slot_rows;  // per slot, the row whose sums it holds
  std::vector<std::vector<double>> prefix(kRowsPerBatch), sums(kRowsPerBatch);
  std::vector<double> window(w * L, 0.0);
  std::vector<std::int64_t> best(shape.size());
  const auto run_batch = [&] {
    parallel_for(
        slot_rows.size(),
        [&](std::size_t slot) {
          row_window_sums(view, shape, slot_rows[slot], r, prefix[slot], sums[slot]);
        },
        threads);
    parallel_for_chunks(
        w, kColumnsPerTask,
        [&](std::size_t, std::size_t first, std::size_t last) {
          double* const columns = window.data() + first * L;
          const std::size_t count = (last - first) * L;
          for (const SlideStep& step : batch) {
            if (step.kind == SlideStep::Kind::best) {
              for (std::size_t x = first; x < last; ++x) {
                const double* costs = window.data() + x * L;  // ties: the smallest label
                best[step.row * w + x] = std::min_element(costs, costs + L) - costs;
              }
              continue;
            }
            const double* row = sums[step.slot].data() + first * L;
            if (step.kind == SlideStep::Kind::enter) {
              for (std::size_t k = 0; k < count; ++k) columns[k] += row[k];
            } else {
              for (std::size_t k = 0; k < count; ++k) columns[k] -= row[k];
            }
          }
        },
        threads);
    batch.clear();
    slot_rows.clear();
  };
  const auto queue_row = [&](SlideStep::Kind kind, std::size_t row) {
    if (slot_rows.size() == kRowsPerBatch) run_batch();
    batch.push_back({kind, row, slot_rows.size()});
    slot_rows.push_back(row);
  };
  std::size_t entered = 0, left = 0;  // rows [left, entered) are in the window
  for (std::size_t y = 0; y < h; ++y) {
    const std::size_t first = y >= r ? y - r : 0;
    const std::size_t end = std::min(h, y + 1 + std::min(r, h));
    for (; entered < end; ++entered) queue_row(SlideStep::Kind::enter, entered);
    for (; left < first; ++left) queue_row(SlideStep::Kind::leave, left);
    batch.push_back({SlideStep::Kind::best, y, 0});
  }
  run_batch();
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
