#pragma once
// The Energy concept: a discrete energy E(x) = sum_v unary(v, x_v) + higher-order terms over
// labelings x of num_variables variables with num_labels labels each.

#include <concepts>
#include <cstddef>
#include <span>

#include "c2f/core/labeling.hpp"

namespace c2f {

namespace detail {
/// The reduction of e by partition p as found by argument-dependent lookup (the free function
/// `reduce` next to the energy type, e.g. c2f::reduce for PairwiseEnergy).
template <class E, class P>
auto reduce_by_adl(const E& e, const P& p) -> decltype(reduce(e, p)) {
  return reduce(e, p);
}
}  // namespace detail

/// How the library reads an energy type. The default forwards to member functions
/// `num_variables()`, `num_labels()`, `unary(v, l)` and `evaluate(labeling)`, and `reduce(e, p)`
/// to the free function `reduce` declared beside the energy type; a foreign type opts in by
/// specialising energy_traits instead of changing the type.
template <class E>
struct energy_traits {
  template <class T = E>
  static auto num_variables(const T& e) -> decltype(e.num_variables()) {
    return e.num_variables();
  }
  template <class T = E>
  static auto num_labels(const T& e) -> decltype(e.num_labels()) {
    return e.num_labels();
  }
  template <class T = E>
  static auto unary(const T& e, std::size_t v, Label l) -> decltype(e.unary(v, l)) {
    return e.unary(v, l);
  }
  template <class T = E>
  static auto evaluate(const T& e, std::span<const Label> x) -> decltype(e.evaluate(x)) {
    return e.evaluate(x);
  }
  template <class T = E, class P>
  static auto reduce(const T& e, const P& partition)
      -> decltype(detail::reduce_by_adl(e, partition)) {
    return detail::reduce_by_adl(e, partition);
  }
};

/// An energy over a finite set of variables sharing one label set.
/// Contract: `evaluate(x)` returns E(x) in double for any valid labeling x (and throws
/// std::invalid_argument for an invalid one); `unary(v, l)` is the unary cost of label l at v.
template <class E>
concept Energy = requires(const E& e, std::span<const Label> x, std::size_t v, Label l) {
  { energy_traits<E>::num_variables(e) } -> std::convertible_to<std::size_t>;
  { energy_traits<E>::num_labels(e) } -> std::convertible_to<int>;
  { energy_traits<E>::unary(e, v, l) } -> std::convertible_to<double>;
  { energy_traits<E>::evaluate(e, x) } -> std::convertible_to<double>;
};

/// The label with the lowest unary cost at variable v (ties: the smallest such label).
template <Energy E>
Label cheapest_label(const E& energy, std::size_t v) {
  const int num_labels = energy_traits<E>::num_labels(energy);
  Label best = 0;
  double best_cost = energy_traits<E>::unary(energy, v, 0);
  for (Label l = 1; l < num_labels; ++l) {
    const double cost = energy_traits<E>::unary(energy, v, l);
    if (cost < best_cost) {
      best_cost = cost;
      best = l;
    }
  }
  return best;
}

}  // namespace c2f
