#include "c2f/core/energy_tally.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "c2f/support/parallel_for.hpp"

namespace c2f {

namespace {

constexpr std::size_t kChunk = PairwiseEnergy::kEvaluationChunk;
/// Fewer touched chunks than this are summed on the calling thread: starting threads would
/// cost more than the sums.
constexpr std::size_t kChunksPerThreadStart = 16;

std::size_t chunks_of(std::size_t count) {
  return (count + kChunk - 1) / kChunk;
}

/// The sum of `sums` in order from zero, as evaluate_unchecked adds its chunks' sums.
double ordered_total(std::span<const double> unary, std::span<const double> pairwise) {
  double total = 0.0;
  for (const double sum : unary) total += sum;
  for (const double sum : pairwise) total += sum;
  return total;
}

}  // namespace

void EnergyTally::bind(const PairwiseEnergy& energy, std::span<const Label> labeling,
                       std::shared_ptr<const EdgeIncidence> incidence, int threads) {
  energy_ = &energy;
  incidence_ = std::move(incidence);
  threads_ = threads;
  const std::size_t unary_chunks = chunks_of(energy.num_variables());
  const std::size_t pairwise_chunks = chunks_of(energy.edges().size());
  unary_.assign(unary_chunks, 0.0);
  pairwise_.assign(pairwise_chunks, 0.0);
  candidate_unary_ = unary_;
  candidate_pairwise_ = pairwise_;
  unary_touched_.assign(unary_chunks, 0);
  pairwise_touched_.assign(pairwise_chunks, 0);
  touched_unary_.resize(unary_chunks);
  touched_pairwise_.resize(pairwise_chunks);
  std::iota(touched_unary_.begin(), touched_unary_.end(), 0U);
  std::iota(touched_pairwise_.begin(), touched_pairwise_.end(), 0U);
  sum_chunks(labeling, touched_unary_, touched_pairwise_);
  touched_unary_.clear();
  touched_pairwise_.clear();
  keep();
}

double EnergyTally::evaluate_changed(std::span<const Label> candidate,
                                     std::span<const VariableIndex> changed) {
  for (const std::uint32_t c : touched_unary_) unary_touched_[c] = 0;
  for (const std::uint32_t c : touched_pairwise_) pairwise_touched_[c] = 0;
  touched_unary_.clear();
  touched_pairwise_.clear();
  auto touch = [](std::vector<std::uint8_t>& marks, std::vector<std::uint32_t>& list,
                  std::size_t index) {
    const std::size_t chunk = index / kChunk;
    if (marks[chunk] != 0) return;
    marks[chunk] = 1;
    list.push_back(static_cast<std::uint32_t>(chunk));
  };
  for (const VariableIndex v : changed) {
    touch(unary_touched_, touched_unary_, v);
    for (const Incidence& inc : incidence_->of(v))
      touch(pairwise_touched_, touched_pairwise_, inc.edge);
  }
  std::copy(unary_.begin(), unary_.end(), candidate_unary_.begin());
  std::copy(pairwise_.begin(), pairwise_.end(), candidate_pairwise_.begin());
  sum_chunks(candidate, touched_unary_, touched_pairwise_);
  candidate_value_ = ordered_total(candidate_unary_, candidate_pairwise_);
  return candidate_value_;
}

void EnergyTally::keep() {
  unary_.swap(candidate_unary_);
  pairwise_.swap(candidate_pairwise_);
  value_ = candidate_value_ = ordered_total(unary_, pairwise_);
  // A keep() without an evaluation between keeps the same labeling.
  std::copy(unary_.begin(), unary_.end(), candidate_unary_.begin());
  std::copy(pairwise_.begin(), pairwise_.end(), candidate_pairwise_.begin());
}

void EnergyTally::sum_chunks(std::span<const Label> x, std::span<const std::uint32_t> unary_chunks,
                             std::span<const std::uint32_t> pairwise_chunks) {
  const PairwiseEnergy& energy = *energy_;
  const std::size_t n = energy.num_variables();
  const std::size_t m = energy.edges().size();
  auto sum = [&](std::size_t task) {
    if (task < unary_chunks.size()) {
      const std::size_t first = unary_chunks[task] * kChunk;
      candidate_unary_[unary_chunks[task]] =
          energy.unary_sum(x, first, std::min(first + kChunk, n));
    } else {
      const std::size_t c = pairwise_chunks[task - unary_chunks.size()];
      const std::size_t first = c * kChunk;
      candidate_pairwise_[c] = energy.pairwise_sum(x, first, std::min(first + kChunk, m));
    }
  };
  const std::size_t tasks = unary_chunks.size() + pairwise_chunks.size();
  if (tasks < kChunksPerThreadStart || resolved_threads(threads_) == 1) {
    for (std::size_t task = 0; task < tasks; ++task) sum(task);
  } else {
    parallel_for(tasks, sum, threads_);
  }
}

}  // namespace c2f
