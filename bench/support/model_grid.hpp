#pragma once
// The cooperative-cut models a segmentation benchmark tries: the product of a lambda, a theta
// and an alpha list.

#include <span>
#include <vector>

#include "c2f/cooperative/coop_energy.hpp"

namespace c2f::bench {

/// Every (lambda, theta, alpha) of the three lists, lambda outermost, alpha innermost.
inline std::vector<CoopParameters> model_grid(std::span<const double> lambdas,
                                              std::span<const double> thetas,
                                              std::span<const double> alphas) {
  std::vector<CoopParameters> models;
  for (const double lambda : lambdas) {
    for (const double theta : thetas) {
      for (const double alpha : alphas) models.push_back({lambda, theta, alpha});
    }
  }
  return models;
}

}  // namespace c2f::bench
