#pragma once
// A read-only view of unary costs stored row-major (num_variables x num_labels) in double or in
// float. Whatever the storage, a cost reads as the double it converts to exactly, so sums over
// costs taken in double are the same for a float array and for the double array of the same
// (float) values.

#include <cstddef>
#include <span>
#include <vector>

#include "c2f/core/labeling.hpp"

namespace c2f {

/// The num_labels costs of one variable.
class UnaryRow {
 public:
  UnaryRow(std::span<const double> costs) noexcept  // NOLINT(google-explicit-constructor)
      : doubles_(costs.data()), size_(costs.size()) {}
  UnaryRow(std::span<const float> costs) noexcept  // NOLINT(google-explicit-constructor)
      : floats_(costs.data()), size_(costs.size()) {}

  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  [[nodiscard]] double operator[](std::size_t l) const noexcept {
    return floats_ != nullptr ? static_cast<double>(floats_[l]) : doubles_[l];
  }

 private:
  const double* doubles_ = nullptr;
  const float* floats_ = nullptr;
  std::size_t size_ = 0;
};

class UnaryCosts {
 public:
  UnaryCosts() = default;
  /// `costs` holds num_variables * num_labels entries; the storage must outlive the view.
  UnaryCosts(std::span<const double> costs, int num_labels) noexcept
      : doubles_(costs), num_labels_(static_cast<std::size_t>(num_labels)) {}
  UnaryCosts(std::span<const float> costs, int num_labels) noexcept
      : floats_(costs), num_labels_(static_cast<std::size_t>(num_labels)), single_(true) {}

  /// True when the costs are stored in float.
  [[nodiscard]] bool single_precision() const noexcept { return single_; }
  /// The number of costs (num_variables * num_labels).
  [[nodiscard]] std::size_t size() const noexcept {
    return single_precision() ? floats_.size() : doubles_.size();
  }
  /// The bytes the stored costs take.
  [[nodiscard]] std::size_t bytes() const noexcept {
    return single_precision() ? floats_.size_bytes() : doubles_.size_bytes();
  }

  [[nodiscard]] double operator()(std::size_t v, Label l) const noexcept {
    const std::size_t i = v * num_labels_ + static_cast<std::size_t>(l);
    return single_precision() ? static_cast<double>(floats_[i]) : doubles_[i];
  }
  [[nodiscard]] UnaryRow row(std::size_t v) const noexcept {
    if (single_precision()) return floats_.subspan(v * num_labels_, num_labels_);
    return doubles_.subspan(v * num_labels_, num_labels_);
  }

  /// visit(std::span<const double>) or visit(std::span<const float>) with all the costs, for
  /// loops that should run on the stored type (a generic lambda serves both).
  template <class Visitor>
  decltype(auto) visit(Visitor&& visitor) const {
    if (single_precision()) return visitor(floats_);
    return visitor(doubles_);
  }

  /// All the costs, each converted to double exactly.
  [[nodiscard]] std::vector<double> to_doubles() const {
    return visit([](auto costs) { return std::vector<double>(costs.begin(), costs.end()); });
  }

 private:
  std::span<const double> doubles_;
  std::span<const float> floats_;
  std::size_t num_labels_ = 0;
  bool single_ = false;
};

}  // namespace c2f
