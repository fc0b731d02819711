#include "level_builder.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "c2f/lift/aggregated_best_labels.hpp"
#include "c2f/lift/block_hierarchy.hpp"
#include "c2f/lift/connected_components.hpp"
#include "c2f/lift/local_grouping.hpp"
#include "c2f/lift/threshold_partition.hpp"
#include "c2f/support/parallel_for.hpp"

namespace c2f::detail {

LevelBuilder::LevelBuilder(std::optional<GridShape> shape, SuperpixelSource superpixels)
    : shape_(shape), superpixels_(std::move(superpixels)) {}

GridShape LevelBuilder::grid_of(const LevelSpec& spec) const {
  if (!shape_) {
    throw std::invalid_argument("schedule: level " + spec.to_string() +
                                " needs a pixel grid, and this energy is none");
  }
  return *shape_;
}

DensePartition LevelBuilder::build(const LevelSpec& spec, const LiftingView& view,
                                   const DensePartition* previous) {
  if (const auto* aggregated = std::get_if<AggregatedLevel>(&spec.partition);
      aggregated != nullptr && aggregated->max_radius > aggregated->radius) {
    return aggregated_within_share(spec, *aggregated, view);
  }
  last_built_ = spec;
  return build_one(spec, view, previous);
}

unsigned LevelBuilder::last_threads() const noexcept {
  const bool split = std::holds_alternative<AggregatedLevel>(last_built_.partition) ||
                     std::holds_alternative<SlicLevel>(last_built_.partition);
  return split ? resolved_threads(threads_) : 1;
}

DensePartition LevelBuilder::build_one(const LevelSpec& spec, const LiftingView& view,
                                       const DensePartition* previous) {
  return connected_if(spec, build_groups(spec, view, previous), view);
}

DensePartition LevelBuilder::connected_if(const LevelSpec& spec, DensePartition partition,
                                          const LiftingView& view) const {
  if (!spec.connected) return partition;
  return shape_ ? connected_components(partition, *shape_)
                : connected_components_along_edges(partition, view);
}

DensePartition LevelBuilder::aggregated_within_share(const LevelSpec& spec,
                                                     const AggregatedLevel& level,
                                                     const LiftingView& view) {
  const auto variables = static_cast<double>(view.num_variables);
  // Off a grid each radius goes on from the last one's sums (the grid's windows cost the same
  // at any radius).
  std::optional<GraphAggregation> rounds;
  if (!shape_) rounds.emplace(view, threads_);
  for (int radius = level.radius;; ++radius) {
    LevelSpec fixed = spec;
    fixed.partition = AggregatedLevel{radius};
    DensePartition partition =
        rounds ? connected_if(fixed, rounds->best_labels(radius, radius < level.max_radius), view)
               : build_one(fixed, view, nullptr);
    const double share = static_cast<double>(partition.num_groups()) / variables;
    if (share <= level.max_share || radius == level.max_radius) {
      last_built_ = fixed;
      return partition;
    }
  }
}

DensePartition LevelBuilder::build_groups(const LevelSpec& spec, const LiftingView& view,
                                          const DensePartition* previous) {
  if (const auto* cp = std::get_if<ColourPassingLevel>(&spec.partition))
    return colour_passing(*cp, view);
  if (const auto* local = std::get_if<LocalGroupingLevel>(&spec.partition)) {
    if (view.pairwise == nullptr) {
      throw std::invalid_argument("schedule: level " + spec.to_string() +
                                  ": local grouping reads a pairwise energy's grid edges, and "
                                  "this energy is of another kind (use cp levels)");
    }
    return local_grouping(*view.pairwise, grid_of(spec), local->labels, local->iterations);
  }
  if (const auto* threshold = std::get_if<ThresholdLevel>(&spec.partition))
    return threshold_partition(view, grid_of(spec), threshold->tau, threshold->radius);
  if (const auto* aggregated = std::get_if<AggregatedLevel>(&spec.partition)) {
    return shape_ ? aggregated_best_labels(view, *shape_, aggregated->radius, threads_)
                  : aggregated_best_labels(view, aggregated->radius, threads_);
  }
  if (const auto* blocks = std::get_if<BlockLevel>(&spec.partition))
    return block_partition(grid_of(spec), static_cast<std::size_t>(blocks->size));
  return superpixels(spec, previous);
}

DensePartition LevelBuilder::colour_passing(const ColourPassingLevel& level,
                                            const LiftingView& view) {
  if (!colour_passing_ || colour_passing_->labels() > level.labels ||
      colour_passing_->iterations() > level.iterations) {
    colour_passing_.emplace(view, level.labels);
  }
  while (colour_passing_->labels() < level.labels) colour_passing_->increase_labels();
  while (colour_passing_->iterations() < level.iterations) colour_passing_->iterate();
  return colour_passing_->partition();
}

DensePartition LevelBuilder::superpixels(const LevelSpec& spec, const DensePartition* previous) {
  const GridShape shape = grid_of(spec);
  DensePartition superpixels =
      superpixels_(std::get<SlicLevel>(spec.partition).region_size, threads_);
  require_grid_size(superpixels.num_variables(), shape,
                    "schedule: level " + LevelSpec{spec.partition}.to_string(),
                    "superpixel partition");
  if (previous == nullptr) return superpixels;
  return intersect(*previous, superpixels);
}

}  // namespace c2f::detail
