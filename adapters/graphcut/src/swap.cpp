#include "c2f/adapters/graphcut/swap.hpp"

#include <stdexcept>

namespace c2f {

void require_semi_metric(const PairwiseEnergy& energy, const char* who) {
  const auto terms = energy.terms();
  std::vector<char> used(terms.size(), 0);
  for (std::size_t e = 0; e < energy.edges().size(); ++e) {
    const Edge& edge = energy.edges()[e];
    if (edge.weight < 0.0) {
      throw std::invalid_argument(std::string(who) + ": edge " + std::to_string(e) +
                                  " has negative weight " + std::to_string(edge.weight) +
                                  "; swap moves need weights >= 0");
    }
    used[edge.term] = 1;
  }
  const int num_labels = energy.num_labels();
  for (std::size_t t = 0; t < terms.size(); ++t) {
    if (!used[t]) continue;
    for (Label a = 0; a < num_labels; ++a) {
      if (terms[t].cost(a, a) != 0.0) {
        throw std::invalid_argument(std::string(who) + ": term " + std::to_string(t) + " (" +
                                    std::string(to_string(terms[t].kind())) +
                                    ") is not a semi-metric: cost(" + std::to_string(a) + ", " +
                                    std::to_string(a) + ") != 0");
      }
      for (Label b = a + 1; b < num_labels; ++b) {
        const double ab = terms[t].cost(a, b);
        if (ab != terms[t].cost(b, a) || ab < 0.0) {
          throw std::invalid_argument(std::string(who) + ": term " + std::to_string(t) + " (" +
                                      std::string(to_string(terms[t].kind())) +
                                      ") is not a semi-metric: cost(" + std::to_string(a) + ", " +
                                      std::to_string(b) + ") is negative or asymmetric");
        }
      }
    }
  }
}

}  // namespace c2f
