#include "c2f/adapters/lbp/lbp.hpp"
#include "c2f/support/enum_names.hpp"
#include "c2f/support/memory_need.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace c2f {

std::string_view to_string(BpSchedule schedule) {
  switch (schedule) {
    case BpSchedule::sequential:
      return "sequential";
    case BpSchedule::parallel:
      return "parallel";
  }
  return "unknown";
}

BpSchedule bp_schedule_from_string(std::string_view text) {
  constexpr BpSchedule kAll[] = {BpSchedule::sequential, BpSchedule::parallel};
  return enum_from_string(text, kAll, "BP schedule");
}

std::string LbpOptions::validate() const {
  if (!(damping >= 0.0 && damping < 1.0)) return "damping must be in [0, 1)";
  return {};
}

std::optional<std::size_t> working_memory_bytes(const LbpOptions& /*options*/,
                                                const ProblemSize& size) {
  return checked_product({size.edges * 4 + size.variables * 3,
                          static_cast<std::size_t>(std::max(size.labels, 1)), sizeof(double)});
}

LbpSolver::LbpSolver(LbpOptions options) : options_(options) {
  if (const std::string problem = options_.validate(); !problem.empty()) {
    throw std::invalid_argument("LbpOptions: " + problem);
  }
}

void LbpSolver::bind(const PairwiseEnergy& energy, std::span<const Label> start) {
  validate_labeling(start, energy.num_variables(), energy.num_labels(), "LbpSolver::bind: start");
  energy_ = &energy;
  num_labels_ = static_cast<std::size_t>(energy.num_labels());
  const auto edges = energy.edges();
  incidence_ = EdgeIncidence(energy);
  messages_.assign(2 * edges.size() * num_labels_, 0.0);
  if (options_.schedule == BpSchedule::parallel) next_messages_.assign(messages_.size(), 0.0);
  belief_.resize(num_labels_);
  h_.resize(num_labels_);
  scratch_.resize(num_labels_);
  best_.assign(start.begin(), start.end());
  decoded_ = best_;
  best_energy_ = energy.evaluate_unchecked(best_);
  last_ = {};
}

void LbpSolver::compute_belief(std::size_t v, std::span<const double> messages,
                               std::span<double> belief) const {
  for (std::size_t l = 0; l < num_labels_; ++l)
    belief[l] = energy_->unary(v, static_cast<Label>(l));
  for (const Incidence& inc : incidence_.of(v)) {
    const double* in = messages.data() + message_index(inc.edge, !inc.is_first);
    for (std::size_t l = 0; l < num_labels_; ++l) belief[l] += in[l];
  }
}

// out(l_to) = min over l_from of h(l_from) + cost of the edge, normalised to minimum 0.
void LbpSolver::compute_message(const Edge& edge, bool from_first, std::span<const double> h,
                                std::span<double> out) {
  const PairwiseTerm& term = energy_->terms()[edge.term];
  const double w = edge.weight;
  const std::size_t L = num_labels_;
  const double h_min = *std::min_element(h.begin(), h.end());
  const bool fast = w >= 0.0 && term.kind() != TermKind::table;
  if (fast && term.kind() == TermKind::potts) {
    for (std::size_t l = 0; l < L; ++l) out[l] = std::min(h[l], h_min + w);
  } else if (fast && term.kind() == TermKind::tsgo_step) {
    const double near = w / 6.0;
    for (std::size_t l = 0; l < L; ++l) {
      double best = std::min(h[l], h_min + w);
      if (l > 0) best = std::min(best, h[l - 1] + near);
      if (l + 1 < L) best = std::min(best, h[l + 1] + near);
      out[l] = best;
    }
  } else if (fast && term.kind() == TermKind::truncated_linear) {
    // L1 distance transform with slope w, then the truncation.
    for (std::size_t l = 0; l < L; ++l) out[l] = h[l];
    for (std::size_t l = 1; l < L; ++l) out[l] = std::min(out[l], out[l - 1] + w);
    for (std::size_t l = L - 1; l-- > 0;) out[l] = std::min(out[l], out[l + 1] + w);
    const double cap = h_min + w * term.truncation();
    for (std::size_t l = 0; l < L; ++l) out[l] = std::min(out[l], cap);
  } else {
    for (std::size_t to = 0; to < L; ++to) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t from = 0; from < L; ++from) {
        const auto a = static_cast<Label>(from_first ? from : to);
        const auto b = static_cast<Label>(from_first ? to : from);
        best = std::min(best, h[from] + w * term.cost(a, b));
      }
      out[to] = best;
    }
  }
  const double out_min = *std::min_element(out.begin(), out.end());
  for (std::size_t l = 0; l < L; ++l) out[l] -= out_min;
}

double LbpSolver::step() {
  if (energy_ == nullptr) throw std::logic_error("LbpSolver::step: call bind() first");
  const std::size_t n = energy_->num_variables();
  const auto edges = energy_->edges();
  const bool parallel = options_.schedule == BpSchedule::parallel;
  std::vector<double>& target = parallel ? next_messages_ : messages_;
  const double damping = options_.damping;
  double message_change = 0.0;
  for (std::size_t v = 0; v < n; ++v) {
    compute_belief(v, messages_, belief_);
    for (const Incidence& inc : incidence_.of(v)) {
      const double* in = messages_.data() + message_index(inc.edge, !inc.is_first);
      for (std::size_t l = 0; l < num_labels_; ++l) h_[l] = belief_[l] - in[l];
      compute_message(edges[inc.edge], inc.is_first, h_, scratch_);
      double* out = target.data() + message_index(inc.edge, inc.is_first);
      const double* old = messages_.data() + message_index(inc.edge, inc.is_first);
      for (std::size_t l = 0; l < num_labels_; ++l) {
        const double value = (1.0 - damping) * scratch_[l] + damping * old[l];
        message_change = std::max(message_change, std::abs(value - old[l]));
        out[l] = value;
      }
    }
  }
  if (parallel) messages_.swap(next_messages_);
  for (std::size_t v = 0; v < n; ++v) {
    compute_belief(v, messages_, belief_);
    decoded_[v] =
        static_cast<Label>(std::min_element(belief_.begin(), belief_.end()) - belief_.begin());
  }
  const double decoded_energy = energy_->evaluate_unchecked(decoded_);
  last_ = {};
  last_.message_change = message_change;
  if (decoded_energy < best_energy_) {
    for (std::size_t v = 0; v < n; ++v) last_.changed += decoded_[v] != best_[v];
    last_.improved = true;
    best_energy_ = decoded_energy;
    best_ = decoded_;
  }
  return best_energy_;
}

}  // namespace c2f
