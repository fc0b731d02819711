#include "c2f/core/pairwise_energy.hpp"
#include "c2f/support/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

namespace c2f {

PairwiseEnergy::PairwiseEnergy(std::size_t num_variables, int num_labels,
                               std::vector<double> unaries, std::vector<PairwiseTerm> terms,
                               std::vector<Edge> edges)
    : num_variables_(num_variables),
      num_labels_(num_labels),
      unaries_(std::move(unaries)),
      terms_(std::move(terms)),
      edges_(std::move(edges)) {
  validate();
}

PairwiseEnergy::PairwiseEnergy(FloatUnaries, std::size_t num_variables, int num_labels,
                               FloatValues unaries, std::vector<PairwiseTerm> terms,
                               std::vector<Edge> edges)
    : num_variables_(num_variables),
      num_labels_(num_labels),
      float_unaries_(std::move(unaries)),
      single_precision_(true),
      terms_(std::move(terms)),
      edges_(std::move(edges)) {
  validate();
}

PairwiseEnergy PairwiseEnergy::with_float_unaries(std::size_t num_variables, int num_labels,
                                                  FloatValues unaries,
                                                  std::vector<PairwiseTerm> terms,
                                                  std::vector<Edge> edges) {
  return {FloatUnaries{},     num_variables,    num_labels,
          std::move(unaries), std::move(terms), std::move(edges)};
}

namespace {

/// The index of the first value of `values` that is not finite, or values.size() when all are.
/// Chunks are scanned without a branch per value (x - x is 0 exactly when x is finite), so the
/// scan vectorises; only a chunk that holds a non-finite value is searched value by value.
template <typename Cost>
std::size_t first_non_finite(std::span<const Cost> values) {
  constexpr std::size_t kChunk = 1024;
  for (std::size_t begin = 0; begin < values.size(); begin += kChunk) {
    const std::size_t end = std::min(begin + kChunk, values.size());
    // A whole chunk's loop has a constant trip count, which GCC vectorises at -O2 (its cheap
    // cost model leaves a loop of unknown count scalar): twice as fast on 1.4 GB of floats.
    const Cost* chunk = values.data() + begin;
    unsigned finite = 1;
    if (end - begin == kChunk) {
      for (std::size_t i = 0; i < kChunk; ++i) finite &= (chunk[i] - chunk[i] == Cost{0});
    } else {
      for (std::size_t i = 0; i < end - begin; ++i) finite &= (chunk[i] - chunk[i] == Cost{0});
    }
    if (finite != 0) continue;
    for (std::size_t i = begin; i < end; ++i)
      if (!std::isfinite(values[i])) return i;
  }
  return values.size();
}

}  // namespace

void PairwiseEnergy::validate() const {
  if (num_labels_ < 1) {
    throw std::invalid_argument("PairwiseEnergy: num_labels must be >= 1, got " +
                                std::to_string(num_labels_));
  }
  if (num_variables_ > std::numeric_limits<VariableIndex>::max()) {
    throw std::invalid_argument("PairwiseEnergy: num_variables " + std::to_string(num_variables_) +
                                " does not fit a 32-bit variable index");
  }
  const std::size_t expected = num_variables_ * static_cast<std::size_t>(num_labels_);
  const UnaryCosts costs = unaries();
  if (costs.size() != expected) {
    throw std::invalid_argument(
        "PairwiseEnergy: unaries has " + std::to_string(costs.size()) +
        " entries, expected num_variables * num_labels = " + std::to_string(expected));
  }
  costs.visit([&](auto stored) {
    const std::size_t i = first_non_finite(stored);
    if (i < stored.size()) {
      throw std::invalid_argument("PairwiseEnergy: unaries: cost of label " +
                                  std::to_string(i % num_labels_) + " at variable " +
                                  std::to_string(i / num_labels_) + " is not finite (" +
                                  std::to_string(stored[i]) + ")");
    }
  });
  for (std::size_t t = 0; t < terms_.size(); ++t) {
    if (!terms_[t].fits(num_labels_))
      terms_[t].validate_for(num_labels_, "PairwiseEnergy: terms[" + std::to_string(t) + "]");
  }
  // One branch-light pass over the edges; a name is built only for an edge that fails (an
  // energy is validated on every construction, e.g. each cooperative-cut step's E_h).
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    const Edge& e = edges_[i];
    const bool valid = e.u < num_variables_ && e.v < num_variables_ && e.u != e.v &&
                       std::isfinite(e.weight) && e.term < terms_.size();
    if (valid) continue;
    const std::string name = "PairwiseEnergy: edges[" + std::to_string(i) + "]";
    if (e.u >= num_variables_ || e.v >= num_variables_) {
      throw std::invalid_argument(
          name + ": endpoint (" + std::to_string(e.u) + ", " + std::to_string(e.v) +
          ") out of range, num_variables = " + std::to_string(num_variables_));
    }
    if (e.u == e.v) {
      throw std::invalid_argument(name + ": self-loop at variable " + std::to_string(e.u));
    }
    if (!std::isfinite(e.weight)) {
      throw std::invalid_argument(name + ": weight is not finite");
    }
    if (e.term >= terms_.size()) {
      throw std::invalid_argument(name + ": term index " + std::to_string(e.term) +
                                  " out of range, there are " + std::to_string(terms_.size()) +
                                  " terms");
    }
  }
}

double PairwiseEnergy::evaluate(std::span<const Label> labeling) const {
  validate_labeling(labeling, num_variables_, num_labels_);
  return evaluate_unchecked(labeling);
}

double PairwiseEnergy::evaluate_unchecked(std::span<const Label> labeling) const noexcept {
  double total = 0.0;
  for (std::size_t first = 0; first < num_variables_; first += kEvaluationChunk)
    total += unary_sum(labeling, first, std::min(first + kEvaluationChunk, num_variables_));
  for (std::size_t first = 0; first < edges_.size(); first += kEvaluationChunk)
    total += pairwise_sum(labeling, first, std::min(first + kEvaluationChunk, edges_.size()));
  return total;
}

double PairwiseEnergy::evaluate_unchecked(std::span<const Label> labeling, int threads) const {
  const std::size_t unary_chunks = (num_variables_ + kEvaluationChunk - 1) / kEvaluationChunk;
  std::vector<double> sums(unary_chunks +
                           (edges_.size() + kEvaluationChunk - 1) / kEvaluationChunk);
  parallel_for(
      sums.size(),
      [&](std::size_t c) {
        if (c < unary_chunks) {
          const std::size_t first = c * kEvaluationChunk;
          sums[c] = unary_sum(labeling, first, std::min(first + kEvaluationChunk, num_variables_));
        } else {
          const std::size_t first = (c - unary_chunks) * kEvaluationChunk;
          sums[c] =
              pairwise_sum(labeling, first, std::min(first + kEvaluationChunk, edges_.size()));
        }
      },
      threads);
  double total = 0.0;  // in evaluate_unchecked's order, from zero
  for (const double sum : sums) total += sum;
  return total;
}

double PairwiseEnergy::unary_sum(std::span<const Label> x, std::size_t first,
                                 std::size_t last) const noexcept {
  double sum = 0.0;
  for (std::size_t v = first; v < last; ++v) sum += unary(v, x[v]);
  return sum;
}

double PairwiseEnergy::pairwise_sum(std::span<const Label> x, std::size_t first,
                                    std::size_t last) const noexcept {
  double sum = 0.0;
  for (std::size_t i = first; i < last; ++i) {
    const Edge& e = edges_[i];
    sum += pairwise_cost(e, x[e.u], x[e.v]);
  }
  return sum;
}

}  // namespace c2f
