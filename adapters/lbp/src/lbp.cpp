#include "c2f/adapters/lbp/lbp.hpp"
#include "c2f/support/enum_names.hpp"
#include "c2f/support/memory_need.hpp"
#include "c2f/support/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace c2f {
namespace {

/// Variables per task of the `parallel` schedule's messages.
constexpr std::size_t kParallelChunk = 1024;
/// Edges per task of the copy of the messages between bands.
constexpr std::size_t kCopyChunk = 1024;
/// Variables per task of decoding.
constexpr std::size_t kDecodeChunk = 4096;

}  // namespace

std::string_view to_string(BpSchedule schedule) {
  switch (schedule) {
    case BpSchedule::sequential:
      return "sequential";
    case BpSchedule::parallel:
      return "parallel";
    case BpSchedule::bands:
      return "bands";
  }
  return "unknown";
}

BpSchedule bp_schedule_from_string(std::string_view text) {
  constexpr BpSchedule kAll[] = {BpSchedule::sequential, BpSchedule::parallel, BpSchedule::bands};
  return enum_from_string(text, kAll, "BP schedule");
}

std::string LbpOptions::validate() const {
  if (!(damping >= 0.0 && damping < 1.0)) return "damping must be in [0, 1)";
  if (threads < 0) return "threads must be >= 0 (0: the machine's cores)";
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
  const std::size_t n = energy.num_variables();
  switch (options_.schedule) {
    case BpSchedule::sequential:
      band_ = std::max<std::size_t>(n, 1);
      break;
    case BpSchedule::parallel:
      band_ = 1;
      break;
    case BpSchedule::bands:
      band_ = options_.band_variables > 0
                  ? options_.band_variables
                  : std::max(LbpOptions::kMinBandVariables,
                             (n + LbpOptions::kDefaultBands - 1) / LbpOptions::kDefaultBands);
      break;
  }
  edges_between_bands_.clear();
  if (options_.schedule == BpSchedule::bands) {
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (edges[e].u / band_ != edges[e].v / band_)
        edges_between_bands_.push_back(static_cast<std::uint32_t>(e));
    }
  }
  const bool buffered = options_.schedule == BpSchedule::parallel || !edges_between_bands_.empty();
  next_messages_.assign(buffered ? messages_.size() : 0, 0.0);
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
                                std::span<double> out) const {
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

double LbpSolver::send_from(std::size_t first, std::size_t last, bool in_place, Scratch& scratch) {
  const auto edges = energy_->edges();
  const double damping = options_.damping;
  double message_change = 0.0;
  for (std::size_t v = first; v < last; ++v) {
    compute_belief(v, messages_, scratch.belief);
    for (const Incidence& inc : incidence_.of(v)) {
      const Edge& edge = edges[inc.edge];
      const std::size_t to = inc.is_first ? edge.v : edge.u;
      const double* in = messages_.data() + message_index(inc.edge, !inc.is_first);
      for (std::size_t l = 0; l < num_labels_; ++l) scratch.h[l] = scratch.belief[l] - in[l];
      compute_message(edge, inc.is_first, scratch.h, scratch.out);
      const std::size_t at = message_index(inc.edge, inc.is_first);
      const bool here = in_place && to >= first && to < last;
      double* out = (here ? messages_ : next_messages_).data() + at;
      const double* old = messages_.data() + at;
      for (std::size_t l = 0; l < num_labels_; ++l) {
        const double value = (1.0 - damping) * scratch.out[l] + damping * old[l];
        message_change = std::max(message_change, std::abs(value - old[l]));
        out[l] = value;
      }
    }
  }
  return message_change;
}

void LbpSolver::decode() {
  parallel_for_chunks(
      energy_->num_variables(), kDecodeChunk,
      [&](std::size_t, std::size_t first, std::size_t last) {
        std::vector<double> belief(num_labels_);
        for (std::size_t v = first; v < last; ++v) {
          compute_belief(v, messages_, belief);
          decoded_[v] =
              static_cast<Label>(std::min_element(belief.begin(), belief.end()) - belief.begin());
        }
      },
      options_.threads);
}

std::size_t LbpSolver::task_variables() const noexcept {
  return options_.schedule == BpSchedule::parallel ? kParallelChunk : band_;
}

unsigned LbpSolver::message_threads() const {
  if (options_.schedule == BpSchedule::sequential || energy_ == nullptr) return 1;
  const std::size_t per_task = task_variables();
  const std::size_t tasks =
      std::max<std::size_t>((energy_->num_variables() + per_task - 1) / per_task, 1);
  return static_cast<unsigned>(std::min<std::size_t>(resolved_threads(options_.threads), tasks));
}

double LbpSolver::step() {
  if (energy_ == nullptr) throw std::logic_error("LbpSolver::step: call bind() first");
  const std::size_t n = energy_->num_variables();
  // Each band's task sends from its own variables; `sequential` is one band sent in place,
  // `parallel` bands of one variable whose every message waits in next_messages_.
  const bool in_place = options_.schedule != BpSchedule::parallel;
  const std::size_t chunk = task_variables();
  const std::size_t tasks = (n + chunk - 1) / chunk;
  std::vector<double> change(tasks, 0.0);
  parallel_for(
      tasks,
      [&](std::size_t t) {
        Scratch scratch(num_labels_);
        change[t] = send_from(t * chunk, std::min(n, (t + 1) * chunk), in_place, scratch);
      },
      options_.schedule == BpSchedule::sequential ? 1 : options_.threads);
  const double message_change =
      change.empty() ? 0.0 : *std::max_element(change.begin(), change.end());
  if (options_.schedule == BpSchedule::parallel) {
    messages_.swap(next_messages_);
  } else if (!edges_between_bands_.empty()) {
    parallel_for_chunks(
        edges_between_bands_.size(), kCopyChunk,
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t i = first; i < last; ++i) {
            const std::size_t at = message_index(edges_between_bands_[i], true);
            std::copy_n(next_messages_.data() + at, 2 * num_labels_, messages_.data() + at);
          }
        },
        options_.threads);
  }
  decode();
  const double decoded_energy = energy_->evaluate_unchecked(decoded_, options_.threads);
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
