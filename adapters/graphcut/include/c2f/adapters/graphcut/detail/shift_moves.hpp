#pragma once
// Internal to ExpansionSolver: the binary problem of a shift move (ExpansionOptions::shift_moves),
// the fusion (Lempitsky et al., "Fusion moves for Markov random field optimization", 2010) of
// the labeling x with x shifted by a fixed number of labels. Every variable may move from its
// label to that label plus the shift, all in one move: a region whose labels should all step
// up or down by one (a slanted surface in stereo, off by one disparity) does so together,
// where an expansion move can only bring it to one common label.

#include <algorithm>
#include <cstddef>
#include <span>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/graphcut/detail/bands.hpp"
#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f::detail {

/// Fills the binary problem (binary_move.hpp's form, one variable per variable, one pair per
/// edge in edge order) of fusing x with y, y_i = x_i + shift clamped to the labels: b_i = 1
/// takes y_i. For every b, E(fused) = E(x) + sum_i d[i] b_i + sum_e p[e] (1 - b_u) b_v.
/// Variables whose shifted label is clamped to their own label cannot change (d[i] = 0 and
/// their terms do not depend on b_i). Writes y into `shifted`. Sizes must match the energy.
inline void shift_problem(const PairwiseEnergy& energy, std::span<const Label> x, int shift,
                          std::span<Label> shifted, std::span<double> d, std::span<double> p) {
  const int top = energy.num_labels() - 1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    shifted[i] = static_cast<Label>(std::clamp(static_cast<int>(x[i]) + shift, 0, top));
    d[i] = energy.unary(i, shifted[i]) - energy.unary(i, x[i]);
  }
  std::fill(p.begin(), p.end(), 0.0);
  const auto edges = energy.edges();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto& edge = edges[e];
    const Label xu = x[edge.u], xv = x[edge.v], yu = shifted[edge.u], yv = shifted[edge.v];
    add_binary_term(d, p, e, static_cast<FlowNode>(edge.u), static_cast<FlowNode>(edge.v),
                    energy.pairwise_cost(edge, xu, xv), energy.pairwise_cost(edge, xu, yv),
                    energy.pairwise_cost(edge, yu, xv), energy.pairwise_cost(edge, yu, yv));
  }
}

/// shift_problem by bands (detail/bands.hpp) on up to `threads` threads: y, then every p[e],
/// then every d[i] as its unary change plus its edges' shares over the variable's incidences,
/// which follow the edge order, so the bits are shift_problem's for every thread count.
inline void shift_problem(const PairwiseEnergy& energy, const EdgeIncidence& incidence,
                          std::span<const Label> x, int shift, std::span<Label> shifted,
                          std::span<double> d, std::span<double> p, int threads) {
  const int top = energy.num_labels() - 1;
  const auto edges = energy.edges();
  for_each_band(
      x.size(),
      [&](std::size_t, std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i)
          shifted[i] = static_cast<Label>(std::clamp(static_cast<int>(x[i]) + shift, 0, top));
      },
      threads);
  for_each_band(
      edges.size(),
      [&](std::size_t, std::size_t first, std::size_t last) {
        for (std::size_t e = first; e < last; ++e) {
          const Edge& edge = edges[e];
          const Label xu = x[edge.u], xv = x[edge.v], yu = shifted[edge.u], yv = shifted[edge.v];
          const double A = energy.pairwise_cost(edge, xu, xv);
          const double B = energy.pairwise_cost(edge, xu, yv);
          const double C = energy.pairwise_cost(edge, yu, xv);
          const double D = energy.pairwise_cost(edge, yu, yv);
          p[e] = 0.0 + (B + C - A - D);  // add_binary_term's sum, onto a zero
        }
      },
      threads);
  for_each_band(
      x.size(),
      [&](std::size_t, std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
          double value = energy.unary(i, shifted[i]) - energy.unary(i, x[i]);
          for (const Incidence& inc : incidence.of(static_cast<VariableIndex>(i))) {
            const Edge& edge = edges[inc.edge];
            const Label xu = x[edge.u], xv = x[edge.v], yu = shifted[edge.u], yv = shifted[edge.v];
            const double C = energy.pairwise_cost(edge, yu, xv);
            value += inc.is_first ? C - energy.pairwise_cost(edge, xu, xv)
                                  : energy.pairwise_cost(edge, yu, yv) - C;
          }
          d[i] = value;
        }
      },
      threads);
}

}  // namespace c2f::detail
