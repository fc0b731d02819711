#include "c2f/lift/colour_passing.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace c2f {

namespace {

/// Assigns dense colours to exact signatures in order of first appearance.
class SignatureColours {
 public:
  explicit SignatureColours(std::size_t expected) { ids_.reserve(expected); }
  std::uint32_t colour_of(const std::u32string& signature) {
    return ids_.try_emplace(signature, static_cast<std::uint32_t>(ids_.size())).first->second;
  }
  [[nodiscard]] std::size_t size() const noexcept { return ids_.size(); }

 private:
  std::unordered_map<std::u32string, std::uint32_t> ids_;
};

/// (cost, label) ordering: lower cost first, then lower label.
bool ranks_before(double cost_a, Label a, double cost_b, Label b) {
  return cost_a < cost_b || (cost_a == cost_b && a < b);
}

}  // namespace

void lowest_cost_labels(UnaryRow row, std::size_t count, std::span<Label> out) {
  std::vector<Label> order(row.size());
  for (std::size_t l = 0; l < order.size(); ++l) order[l] = static_cast<Label>(l);
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end(),
                    [&](Label a, Label b) { return ranks_before(row[a], a, row[b], b); });
  std::copy_n(order.begin(), count, out.begin());
}

LiftingView lifting_view(const PairwiseEnergy& energy) {
  LiftingView view;
  view.num_variables = energy.num_variables();
  view.num_labels = energy.num_labels();
  view.unaries = energy.unaries();
  view.pairwise = &energy;
  const auto edges = energy.edges();
  std::unordered_map<std::uint64_t, std::uint32_t> weight_ids;
  SignatureColours pair_colours(16);
  std::u32string signature;
  view.factors.resize(edges.size());
  // Each term's symmetry once: a table term's is a scan of its table.
  std::vector<std::uint8_t> symmetric(energy.terms().size());
  for (std::size_t t = 0; t < symmetric.size(); ++t)
    symmetric[t] = energy.terms()[t].is_symmetric() ? 1 : 0;
  // An edge of the same term and weight as the edge before (every edge of a grid of one
  // weight) has its colour: the maps are asked only when either changes.
  std::uint32_t last_term = 0;
  std::uint64_t last_bits = 0;
  ColourFactor last{};
  bool have_last = false;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double weight = edges[e].weight == 0.0 ? 0.0 : edges[e].weight;  // -0 == +0
    const auto bits = std::bit_cast<std::uint64_t>(weight);
    if (!have_last || edges[e].term != last_term || bits != last_bits) {
      const auto weight_id =
          weight_ids.try_emplace(bits, static_cast<std::uint32_t>(weight_ids.size())).first->second;
      signature = {static_cast<char32_t>(edges[e].term), static_cast<char32_t>(weight_id)};
      last = {0, 0, pair_colours.colour_of(signature), symmetric[edges[e].term] != 0};
      last_term = edges[e].term;
      last_bits = bits;
      have_last = true;
    }
    view.factors[e] = {edges[e].u, edges[e].v, last.colour, last.symmetric};
  }
  return view;
}

ColourPassing::ColourPassing(const PairwiseEnergy& energy, int labels)
    : ColourPassing(lifting_view(energy), labels) {}

ColourPassing::ColourPassing(const LiftingView& view, int labels)
    : unaries_(view.unaries),
      num_labels_(view.num_labels),
      factors_(view.factors),
      labels_(labels) {
  if (labels < 1 || labels > view.num_labels) {
    throw std::invalid_argument("colour passing: N_L must be in [1, " +
                                std::to_string(view.num_labels) + "], got " +
                                std::to_string(labels));
  }
  const std::size_t n = view.num_variables;
  variable_colour_.assign(n, 0);
  num_variable_colours_ = n == 0 ? 0 : 1;

  // Unary factors: the ordered tuple of the N_L lowest-cost labels.
  const auto count = static_cast<std::size_t>(labels);
  std::vector<Label> top(count);
  last_label_.resize(n);
  last_cost_.resize(n);
  unary_colour_.resize(n);
  SignatureColours unary_colours(n / 4 + 16);
  std::u32string signature;
  for (std::size_t v = 0; v < n; ++v) {
    const UnaryRow row = view.unaries.row(v);
    lowest_cost_labels(row, count, top);
    signature.assign(top.begin(), top.end());
    unary_colour_[v] = unary_colours.colour_of(signature);
    last_label_[v] = top.back();
    last_cost_[v] = row[static_cast<std::size_t>(top.back())];
  }

  // Pairwise factors: the view's colours, made dense in order of first appearance.
  SignatureColours pair_colours(16);
  pair_colour_.resize(factors_.size());
  pair_symmetric_.resize(factors_.size());
  for (std::size_t e = 0; e < factors_.size(); ++e) {
    signature = {static_cast<char32_t>(factors_[e].colour)};
    pair_colour_[e] = pair_colours.colour_of(signature);
    pair_symmetric_[e] = factors_[e].symmetric;
  }

  incidence_ = EdgeIncidence(n, std::span<const ColourFactor>(factors_));
}

bool ColourPassing::iterate() {
  const std::size_t n = variable_colour_.size();
  // Variables -> pairwise factors.
  SignatureColours pair_colours(factors_.size() / 4 + 16);
  std::vector<std::uint32_t> new_pair_colour(factors_.size());
  std::u32string signature;
  for (std::size_t e = 0; e < factors_.size(); ++e) {
    char32_t a = variable_colour_[factors_[e].u];
    char32_t b = variable_colour_[factors_[e].v];
    if (pair_symmetric_[e] && a > b) std::swap(a, b);
    signature = {static_cast<char32_t>(pair_colour_[e]), a, b};
    new_pair_colour[e] = pair_colours.colour_of(signature);
  }
  pair_colour_.swap(new_pair_colour);
  // Factors -> variables.
  SignatureColours variable_colours(n / 4 + 16);
  std::vector<std::uint32_t> new_variable_colour(n);
  std::vector<char32_t> incoming;
  for (std::size_t v = 0; v < n; ++v) {
    incoming.clear();
    for (const Incidence& inc : incidence_.of(v)) {
      const std::uint32_t e = inc.edge;
      const std::uint32_t position = pair_symmetric_[e] ? 0 : (inc.is_first ? 1 : 2);
      incoming.push_back(static_cast<char32_t>(pair_colour_[e] * 3 + position));
    }
    std::sort(incoming.begin(), incoming.end());
    signature = {static_cast<char32_t>(variable_colour_[v]),
                 static_cast<char32_t>(unary_colour_[v])};
    signature.append(incoming.begin(), incoming.end());
    new_variable_colour[v] = variable_colours.colour_of(signature);
  }
  variable_colour_.swap(new_variable_colour);
  const bool finer = variable_colours.size() > num_variable_colours_;
  num_variable_colours_ = variable_colours.size();
  ++iterations_;
  return finer;
}

void ColourPassing::increase_labels() {
  if (labels_ >= num_labels_) {
    throw std::logic_error("colour passing: N_L is already the number of labels (" +
                           std::to_string(labels_) + ")");
  }
  const std::size_t n = variable_colour_.size();
  const int num_labels = num_labels_;
  SignatureColours variable_colours(n / 4 + 16);
  SignatureColours unary_colours(n / 4 + 16);
  std::u32string signature;
  for (std::size_t v = 0; v < n; ++v) {
    // The next label in (cost, label) order after the current last one.
    Label next = -1;
    double next_cost = 0.0;
    for (Label l = 0; l < num_labels; ++l) {
      const double cost = unaries_(v, l);
      if (ranks_before(last_cost_[v], last_label_[v], cost, l) &&
          (next < 0 || ranks_before(cost, l, next_cost, next))) {
        next = l;
        next_cost = cost;
      }
    }
    last_label_[v] = next;
    last_cost_[v] = next_cost;
    signature = {static_cast<char32_t>(unary_colour_[v]), static_cast<char32_t>(next)};
    unary_colour_[v] = unary_colours.colour_of(signature);
    signature[0] = static_cast<char32_t>(variable_colour_[v]);
    variable_colour_[v] = variable_colours.colour_of(signature);
  }
  num_variable_colours_ = variable_colours.size();
  ++labels_;
}

DensePartition ColourPassing::partition() const {
  // Colours are dense and numbered by first appearance in variable order already, except
  // after construction (all 0), which is dense too.
  return DensePartition(
      std::vector<VariableIndex>(variable_colour_.begin(), variable_colour_.end()),
      num_variable_colours_);
}

}  // namespace c2f
