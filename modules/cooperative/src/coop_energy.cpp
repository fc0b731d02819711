#include "c2f/cooperative/coop_energy.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

namespace c2f {

namespace {

[[noreturn]] void invalid(const std::string& message) {
  throw std::invalid_argument("CoopEnergy: " + message);
}

bool finite_nonnegative(double value) {
  return std::isfinite(value) && value >= 0.0;
}

}  // namespace

std::string CoopParameters::validate() const {
  if (!(std::isfinite(lambda) && lambda >= 0.0)) return "lambda must be finite and >= 0";
  if (!(std::isfinite(theta) && theta >= 0.0)) return "theta must be finite and >= 0";
  if (!(alpha >= 0.0 && alpha < 1.0)) return "alpha must be in [0, 1)";
  return {};
}

CoopEnergy::CoopEnergy(std::size_t num_variables, int num_labels, std::vector<double> unaries,
                       int num_classes, std::vector<double> class_totals, CoopParameters parameters,
                       std::vector<CoopEdge> edges, std::vector<ClassWeight> entries)
    : num_variables_(num_variables),
      num_labels_(num_labels),
      unaries_(std::move(unaries)),
      num_classes_(num_classes),
      class_totals_(std::move(class_totals)),
      parameters_(parameters),
      edges_(std::move(edges)),
      entries_(std::move(entries)) {
  if (num_labels_ < 1) invalid("num_labels must be >= 1");
  if (num_classes_ < 1) invalid("num_classes must be >= 1");
  if (const std::string problem = parameters_.validate(); !problem.empty()) invalid(problem);
  if (unaries_.size() != num_variables_ * static_cast<std::size_t>(num_labels_)) {
    invalid("unaries has " + std::to_string(unaries_.size()) + " entries, expected " +
            std::to_string(num_variables_ * static_cast<std::size_t>(num_labels_)));
  }
  for (std::size_t i = 0; i < unaries_.size(); ++i) {
    if (!std::isfinite(unaries_[i])) invalid("unaries[" + std::to_string(i) + "] is not finite");
  }
  if (class_totals_.size() != static_cast<std::size_t>(num_classes_)) {
    invalid("class_totals has " + std::to_string(class_totals_.size()) + " entries, expected " +
            std::to_string(num_classes_));
  }
  for (const double total : class_totals_) {
    if (!finite_nonnegative(total)) invalid("class totals must be finite and >= 0");
  }
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const CoopEdge& edge = edges_[e];
    if (edge.u >= num_variables_ || edge.v >= num_variables_ || edge.u == edge.v) {
      invalid("edge " + std::to_string(e) + " must join two different variables < " +
              std::to_string(num_variables_));
    }
    if (!(edge.first <= edge.middle && edge.middle <= edge.last && edge.last <= entries_.size()))
      invalid("edge " + std::to_string(e) + " has entry ranges outside the entries");
  }
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (entries_[i].edge_class > static_cast<std::uint32_t>(num_classes_) ||
        !finite_nonnegative(entries_[i].weight)) {
      invalid("entries[" + std::to_string(i) +
              "] needs a class <= " + std::to_string(num_classes_) + " and a finite weight >= 0");
    }
  }
}

double CoopEnergy::concave_cost(int edge_class, double s) const noexcept {
  const double alpha = parameters_.alpha;
  return std::min(s, alpha * s + (1.0 - alpha) * breakpoint(edge_class));
}

std::vector<double> CoopEnergy::cut_sizes(std::span<const Label> labeling, double* linear) const {
  const auto K = static_cast<std::size_t>(num_classes_);
  std::vector<double> sizes(static_cast<std::size_t>(num_labels_) * K, 0.0);
  double linear_part = 0.0;
  auto add_side = [&](std::span<const ClassWeight> side, Label label) {
    for (const ClassWeight& entry : side) {
      if (entry.edge_class == K) {
        linear_part += 0.5 * entry.weight;
      } else {
        sizes[static_cast<std::size_t>(label) * K + entry.edge_class] += 0.5 * entry.weight;
      }
    }
  };
  for (const CoopEdge& edge : edges_) {
    const Label a = labeling[edge.u];
    const Label b = labeling[edge.v];
    if (a == b) continue;
    add_side(u_side(edge), a);
    add_side(v_side(edge), b);
  }
  if (linear != nullptr) *linear = linear_part;
  return sizes;
}

double CoopEnergy::evaluate(std::span<const Label> labeling) const {
  validate_labeling(labeling, num_variables_, num_labels_, "CoopEnergy::evaluate");
  return evaluate_unchecked(labeling);
}

double CoopEnergy::evaluate_unchecked(std::span<const Label> labeling) const {
  double total = 0.0;
  for (std::size_t v = 0; v < num_variables_; ++v) total += unary(v, labeling[v]);
  double linear = 0.0;
  const std::vector<double> sizes = cut_sizes(labeling, &linear);
  double pairwise = linear;
  const auto K = static_cast<std::size_t>(num_classes_);
  for (std::size_t i = 0; i < sizes.size(); ++i)
    pairwise += concave_cost(static_cast<int>(i % K), sizes[i]);
  return total + parameters_.lambda * pairwise;
}

CoopEnergy reduce(const CoopEnergy& energy, const GroupIds& partition) {
  if (partition.num_variables() != energy.num_variables()) {
    throw std::invalid_argument("reduce: the partition has " +
                                std::to_string(partition.num_variables()) +
                                " variables, the energy " + std::to_string(energy.num_variables()));
  }
  const std::size_t groups = partition.num_groups();
  const auto L = static_cast<std::size_t>(energy.num_labels());
  std::vector<double> unaries(groups * L, 0.0);
  for (std::size_t v = 0; v < energy.num_variables(); ++v) {
    const std::size_t g = partition[v];
    for (std::size_t l = 0; l < L; ++l) unaries[g * L + l] += energy.unaries()[v * L + l];
  }
  // Entries of edges between groups as (smaller group, larger group, side, class, weight),
  // put in order of (a, b, side, class) and merged: one edge per group pair, one entry per
  // (side, class). Equal keys keep the order of the energy's edges and entries, so a merged
  // weight is summed in that order. The order: by a in buckets (a counting pass over the edges),
  // then each bucket (a group's boundary, small) sorted by (b, side, class, position).
  struct Item {
    VariableIndex a, b;
    std::uint8_t side;  // 0: a's side, 1: b's side
    std::uint32_t edge_class;
    double weight;
  };
  std::vector<std::size_t> bucket_start(groups + 1, 0);
  for (const CoopEdge& edge : energy.edges()) {
    const VariableIndex gu = partition[edge.u];
    const VariableIndex gv = partition[edge.v];
    if (gu != gv) bucket_start[std::min(gu, gv) + 1] += edge.last - edge.first;
  }
  for (std::size_t g = 0; g < groups; ++g) bucket_start[g + 1] += bucket_start[g];
  std::vector<Item> items(bucket_start[groups]);
  std::vector<std::size_t> next(bucket_start.begin(), bucket_start.end() - 1);
  for (const CoopEdge& edge : energy.edges()) {
    const VariableIndex gu = partition[edge.u];
    const VariableIndex gv = partition[edge.v];
    if (gu == gv) continue;  // never cut
    const bool flipped = gv < gu;
    const VariableIndex a = flipped ? gv : gu;
    const VariableIndex b = flipped ? gu : gv;
    std::size_t& slot = next[a];
    for (const ClassWeight& entry : energy.u_side(edge))
      items[slot++] = {a, b, static_cast<std::uint8_t>(flipped ? 1 : 0), entry.edge_class,
                       entry.weight};
    for (const ClassWeight& entry : energy.v_side(edge))
      items[slot++] = {a, b, static_cast<std::uint8_t>(flipped ? 0 : 1), entry.edge_class,
                       entry.weight};
  }
  for (std::size_t g = 0; g < groups; ++g) {
    std::stable_sort(items.begin() + static_cast<std::ptrdiff_t>(bucket_start[g]),
                     items.begin() + static_cast<std::ptrdiff_t>(bucket_start[g + 1]),
                     [](const Item& x, const Item& y) {
                       return std::tie(x.b, x.side, x.edge_class) <
                              std::tie(y.b, y.side, y.edge_class);
                     });
  }
  std::vector<CoopEdge> edges;
  std::vector<ClassWeight> entries;
  for (std::size_t i = 0; i < items.size();) {
    CoopEdge edge{items[i].a, items[i].b, static_cast<std::uint32_t>(entries.size()), 0, 0};
    edge.middle = edge.first;
    for (; i < items.size() && items[i].a == edge.u && items[i].b == edge.v;) {
      ClassWeight merged{items[i].edge_class, 0.0};
      const std::uint8_t side = items[i].side;
      for (; i < items.size() && items[i].a == edge.u && items[i].b == edge.v &&
             items[i].side == side && items[i].edge_class == merged.edge_class;
           ++i) {
        merged.weight += items[i].weight;
      }
      entries.push_back(merged);
      if (side == 0) edge.middle = static_cast<std::uint32_t>(entries.size());
    }
    edge.last = static_cast<std::uint32_t>(entries.size());
    edges.push_back(edge);
  }
  return CoopEnergy(groups, energy.num_labels(), std::move(unaries), energy.num_classes(),
                    std::vector<double>(energy.class_totals().begin(), energy.class_totals().end()),
                    energy.parameters(), std::move(edges), std::move(entries));
}

LiftingView lifting_view(const CoopEnergy& energy) {
  LiftingView view;
  view.num_variables = energy.num_variables();
  view.num_labels = energy.num_labels();
  view.unaries = UnaryCosts(energy.unaries(), energy.num_labels());
  // Colours are numbered in the order their signatures (u-side classes, then v-side classes)
  // first occur. An edge with one class on each side, as every edge of the original problem,
  // finds its colour in a table by its class pair; any other signature in a map.
  std::uint32_t colour_count = 0;
  constexpr std::uint32_t kUnseen = ~0U;
  const auto classes = static_cast<std::size_t>(energy.num_classes()) + 1;  // K: the linear one
  std::vector<std::uint32_t> pair_colours(classes * classes, kUnseen);
  std::map<std::vector<std::uint32_t>, std::uint32_t> colours;
  std::vector<std::uint32_t> signature;
  view.factors.reserve(energy.edges().size());
  for (const CoopEdge& edge : energy.edges()) {
    const std::span<const ClassWeight> u_side = energy.u_side(edge);
    const std::span<const ClassWeight> v_side = energy.v_side(edge);
    std::uint32_t colour;
    if (u_side.size() == 1 && v_side.size() == 1) {
      std::uint32_t& known = pair_colours[u_side[0].edge_class * classes + v_side[0].edge_class];
      if (known == kUnseen) known = colour_count++;
      colour = known;
    } else {
      signature.clear();
      for (const ClassWeight& entry : u_side) signature.push_back(entry.edge_class);
      signature.push_back(~0U);  // separates the sides
      for (const ClassWeight& entry : v_side) signature.push_back(entry.edge_class);
      const auto [it, inserted] = colours.try_emplace(signature, colour_count);
      if (inserted) ++colour_count;
      colour = it->second;
    }
    view.factors.push_back({edge.u, edge.v, colour, false});
  }
  return view;
}

CoopAuxiliary::CoopAuxiliary(int num_labels, int num_classes)
    : num_labels_(num_labels),
      num_classes_(num_classes),
      on_(static_cast<std::size_t>(num_labels * num_classes), 1) {}

CoopAuxiliary CoopAuxiliary::optimal_for(const CoopEnergy& energy,
                                         std::span<const Label> labeling) {
  return optimal_for(energy, energy.cut_sizes(labeling));
}

CoopAuxiliary CoopAuxiliary::optimal_for(const CoopEnergy& energy,
                                         std::span<const double> cut_sizes) {
  CoopAuxiliary h(energy.num_labels(), energy.num_classes());
  for (int l = 0; l < h.num_labels_; ++l) {
    for (int g = 0; g < h.num_classes_; ++g) {
      h.set(l, g,
            cut_sizes[static_cast<std::size_t>(l * h.num_classes_ + g)] <= energy.breakpoint(g));
    }
  }
  return h;
}

std::size_t CoopAuxiliary::differences(const CoopAuxiliary& other) const noexcept {
  std::size_t count = 0;
  for (std::size_t i = 0; i < on_.size() && i < other.on_.size(); ++i)
    count += on_[i] != other.on_[i];
  return count;
}

PairwiseEnergy pairwise_energy(const CoopEnergy& energy, const CoopAuxiliary& h) {
  const int L = energy.num_labels();
  const int K = energy.num_classes();
  if (h.num_labels() != L || h.num_classes() != K) {
    throw std::invalid_argument("pairwise_energy: h is " + std::to_string(h.num_labels()) + "x" +
                                std::to_string(h.num_classes()) + ", the energy has " +
                                std::to_string(L) + " labels and " + std::to_string(K) +
                                " classes");
  }
  const double lambda = energy.parameters().lambda;
  const double alpha = energy.parameters().alpha;
  auto slope = [&](int label, std::uint32_t edge_class) {
    return static_cast<int>(edge_class) == K || h.linear(label, static_cast<int>(edge_class))
               ? 1.0
               : alpha;
  };
  // Per edge: cost(a, b) = [a != b] (U[a] + V[b]) with U, V the sides' slope-weighted halves,
  // scaled by the edge's total weight W so that edges of one class composition share a term.
  std::vector<PairwiseTerm> terms;
  std::unordered_map<std::string, std::uint32_t> term_of;
  std::vector<Edge> edges;
  edges.reserve(energy.edges().size());
  std::vector<double> side_u(static_cast<std::size_t>(L)), side_v(static_cast<std::size_t>(L));
  std::vector<double> table(static_cast<std::size_t>(L * L));
  std::string key;
  // An edge with one entry of equal weight on each side, as every edge of the original problem,
  // has the term of its class pair: found once per pair, then read from this table.
  constexpr std::uint32_t kUnseen = ~0U;
  const auto classes = static_cast<std::size_t>(K) + 1;
  std::vector<std::uint32_t> pair_terms(classes * classes, kUnseen);
  for (const CoopEdge& edge : energy.edges()) {
    const std::span<const ClassWeight> u_entries = energy.u_side(edge);
    const std::span<const ClassWeight> v_entries = energy.v_side(edge);
    double total = 0.0;
    for (const ClassWeight& entry : u_entries) total += entry.weight;
    for (const ClassWeight& entry : v_entries) total += entry.weight;
    if (!(total > 0.0)) continue;
    std::uint32_t* pair_term = nullptr;
    if (u_entries.size() == 1 && v_entries.size() == 1 &&
        u_entries[0].weight == v_entries[0].weight) {
      pair_term = &pair_terms[u_entries[0].edge_class * classes + v_entries[0].edge_class];
      if (*pair_term != kUnseen) {
        edges.push_back({edge.u, edge.v, total, *pair_term});
        continue;
      }
    }
    for (int l = 0; l < L; ++l) {
      double u_sum = 0.0, v_sum = 0.0;
      for (const ClassWeight& entry : u_entries)
        u_sum += (entry.weight / total) * slope(l, entry.edge_class);
      for (const ClassWeight& entry : v_entries)
        v_sum += (entry.weight / total) * slope(l, entry.edge_class);
      side_u[static_cast<std::size_t>(l)] = 0.5 * lambda * u_sum;
      side_v[static_cast<std::size_t>(l)] = 0.5 * lambda * v_sum;
    }
    key.assign(reinterpret_cast<const char*>(side_u.data()), side_u.size() * sizeof(double));
    key.append(reinterpret_cast<const char*>(side_v.data()), side_v.size() * sizeof(double));
    auto [it, inserted] = term_of.try_emplace(key, static_cast<std::uint32_t>(terms.size()));
    if (inserted) {
      for (int a = 0; a < L; ++a) {
        for (int b = 0; b < L; ++b) {
          table[static_cast<std::size_t>(a * L + b)] =
              a == b ? 0.0
                     : side_u[static_cast<std::size_t>(a)] + side_v[static_cast<std::size_t>(b)];
        }
      }
      terms.push_back(PairwiseTerm::table(L, table));
    }
    if (pair_term != nullptr) *pair_term = it->second;
    edges.push_back({edge.u, edge.v, total, it->second});
  }
  if (terms.empty()) terms.push_back(PairwiseTerm::potts());
  return PairwiseEnergy(energy.num_variables(), L,
                        std::vector<double>(energy.unaries().begin(), energy.unaries().end()),
                        std::move(terms), std::move(edges));
}

double aux_constant(const CoopEnergy& energy, const CoopAuxiliary& h) {
  double total = 0.0;
  for (int l = 0; l < h.num_labels(); ++l) {
    for (int g = 0; g < h.num_classes(); ++g) {
      if (!h.linear(l, g)) total += (1.0 - energy.parameters().alpha) * energy.breakpoint(g);
    }
  }
  return energy.parameters().lambda * total;
}

std::size_t energy_memory_bytes(const CoopEnergy& energy) {
  return energy.unaries().size_bytes() + energy.class_totals().size_bytes() +
         energy.edges().size_bytes() + energy.entries().size_bytes();
}

PairwiseEnergy potts_energy(const CoopEnergy& energy) {
  std::vector<Edge> edges;
  edges.reserve(energy.edges().size());
  for (const CoopEdge& edge : energy.edges()) {
    double total = 0.0;
    for (const ClassWeight& entry : energy.u_side(edge)) total += entry.weight;
    for (const ClassWeight& entry : energy.v_side(edge)) total += entry.weight;
    edges.push_back({edge.u, edge.v, 0.5 * energy.parameters().lambda * total, 0});
  }
  return PairwiseEnergy(energy.num_variables(), energy.num_labels(),
                        std::vector<double>(energy.unaries().begin(), energy.unaries().end()),
                        {PairwiseTerm::potts()}, std::move(edges));
}

}  // namespace c2f
