#include "c2f/lift/schedule_provider.hpp"

#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "c2f/lift/auto_levels.hpp"
#include "level_builder.hpp"

namespace c2f {

ScheduleProvider::ScheduleProvider(Schedule schedule, GridShape shape, SuperpixelSource superpixels)
    : schedule_(std::move(schedule)), shape_(shape) {
  if (shape_->size() == 0) throw std::invalid_argument("ScheduleProvider: the grid is empty");
  for (const LevelSpec& level : schedule_.levels) {
    if (std::holds_alternative<SlicLevel>(level.partition) && !superpixels) {
      throw std::invalid_argument(
          "ScheduleProvider: level " + level.to_string() +
          " needs superpixels of an image, and no superpixel source was given");
    }
  }
  builder_ = std::make_unique<detail::LevelBuilder>(shape_, std::move(superpixels));
}

ScheduleProvider::ScheduleProvider(Schedule schedule) : schedule_(std::move(schedule)) {
  if (const std::string problem = schedule_.validate_without_grid(); !problem.empty())
    throw std::invalid_argument("ScheduleProvider: " + problem);
  builder_ = std::make_unique<detail::LevelBuilder>(std::nullopt, SuperpixelSource{});
}

ScheduleProvider::~ScheduleProvider() = default;
ScheduleProvider::ScheduleProvider(ScheduleProvider&&) noexcept = default;

void ScheduleProvider::set_threads(int threads) noexcept {
  builder_->set_threads(threads);
}
ScheduleProvider& ScheduleProvider::operator=(ScheduleProvider&&) noexcept = default;

void ScheduleProvider::keep_apart(std::span<const int> classes) {
  if (shape_ && classes.size() != shape_->size()) {
    throw std::invalid_argument("ScheduleProvider::keep_apart: " + std::to_string(classes.size()) +
                                " classes for a grid of " + std::to_string(shape_->size()) +
                                " pixels");
  }
  for (std::size_t v = 0; v < classes.size(); ++v) {
    if (classes[v] < 0) {
      throw std::invalid_argument("ScheduleProvider::keep_apart: classes[" + std::to_string(v) +
                                  "] = " + std::to_string(classes[v]) + " is negative");
    }
  }
  apart_ = DensePartition::from_ids(classes);
}

std::optional<DensePartition> ScheduleProvider::next(const LiftingView& energy) {
  if (shape_) require_grid_size(energy.num_variables, *shape_, "ScheduleProvider");
  if (apart_ && apart_->num_variables() != energy.num_variables) {
    throw std::invalid_argument(
        "ScheduleProvider: keep_apart has " + std::to_string(apart_->num_variables()) +
        " classes for an energy of " + std::to_string(energy.num_variables) + " variables");
  }
  const auto start = std::chrono::steady_clock::now();
  if (!started_) {
    started_ = true;
    if (const std::string problem = schedule_.validate(energy.num_labels); !problem.empty())
      throw std::invalid_argument("schedule: " + problem);
    levels_ = schedule_.auto_fractions.empty() ? schedule_.levels
                                               : auto_levels(energy, schedule_.auto_fractions);
  }
  if (position_ >= levels_.size()) return std::nullopt;
  const LevelSpec& spec = levels_[position_];
  DensePartition partition = builder_->build(spec, energy, previous_ ? &*previous_ : nullptr);
  if (apart_) partition = intersect(partition, *apart_);
  ++position_;
  // A level that chose its own radius reports the one it chose, then its text.
  const LevelSpec& built = builder_->last_built();
  std::string text = built.to_string();
  if (built != spec) text += " (" + spec.to_string() + ")";
  reports_.push_back(
      {std::move(text), partition.num_groups(),
       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
       builder_->last_threads()});
  previous_ = partition;
  return partition;
}

}  // namespace c2f
