#pragma once
// A stereo cost volume for the left view: cost(x, y, d) for disparities d = 0..L-1, stored
// pixel-major ((y * width + x) * L + d) in float, the layout PairwiseEnergy takes as unaries
// (PairwiseEnergy::with_float_unaries). Stages compute in double and store each cost rounded
// to float: half the memory and traffic of the largest array of the data preparation. A left
// pixel (x, y) with disparity d matches the right pixel (x - d, y); (x, d) is "valid" when
// d <= x.

#include <algorithm>
#include <cstddef>
#include <span>

#include "c2f/core/default_init_allocator.hpp"

namespace c2f::vision {

class CostVolume {
 public:
  /// Throws std::invalid_argument unless width, height and labels are >= 1. `fill` is stored
  /// rounded to float.
  CostVolume(std::size_t width, std::size_t height, int labels, double fill = 0.0);
  /// Tag of the constructor that leaves the cells unwritten.
  struct Unwritten {};
  /// As above, with the cells allocated but not written: the producer writes every cell (on
  /// any threads) before anything reads one, so each page is touched first by the thread that
  /// computes it, not by a serial fill.
  CostVolume(std::size_t width, std::size_t height, int labels, Unwritten);

  [[nodiscard]] std::size_t width() const noexcept { return width_; }
  [[nodiscard]] std::size_t height() const noexcept { return height_; }
  [[nodiscard]] int labels() const noexcept { return labels_; }
  [[nodiscard]] bool valid(std::size_t x, int d) const noexcept {
    return static_cast<std::size_t>(d) <= x;
  }
  /// How many labels are valid at column x: d = 0 .. valid_labels(x) - 1.
  [[nodiscard]] std::size_t valid_labels(std::size_t x) const noexcept {
    return std::min(static_cast<std::size_t>(labels_), x + 1);
  }

  float& at(std::size_t x, std::size_t y, int d) noexcept {
    return data_[(y * width_ + x) * static_cast<std::size_t>(labels_) +
                 static_cast<std::size_t>(d)];
  }
  [[nodiscard]] float at(std::size_t x, std::size_t y, int d) const noexcept {
    return data_[(y * width_ + x) * static_cast<std::size_t>(labels_) +
                 static_cast<std::size_t>(d)];
  }
  [[nodiscard]] const FloatValues& data() const noexcept { return data_; }
  /// The costs, pixel-major, for passes over the whole volume.
  [[nodiscard]] std::span<float> values() noexcept { return data_; }
  /// Moves the costs out (for PairwiseEnergy); the volume is empty afterwards.
  FloatValues release() noexcept { return std::move(data_); }

 private:
  std::size_t width_, height_;
  int labels_;
  FloatValues data_;
};

}  // namespace c2f::vision
