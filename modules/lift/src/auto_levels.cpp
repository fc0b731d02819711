#include "c2f/lift/auto_levels.hpp"

#include <cmath>
#include <cstddef>

#include "c2f/lift/colour_passing.hpp"

namespace c2f {

std::vector<LevelSpec> auto_levels(const LiftingView& energy, std::span<const double> fractions) {
  std::vector<LevelSpec> levels;
  if (fractions.empty()) return levels;
  struct Candidate {
    LevelSpec spec;
    std::size_t groups;
  };
  std::vector<Candidate> chain;
  ColourPassing cp(energy, 1);
  cp.iterate();
  chain.push_back({LevelSpec{ColourPassingLevel{1, 1}}, cp.num_groups()});
  const double n = static_cast<double>(energy.num_variables);
  const double largest = fractions.back() * n;
  for (int step = 0; step < 16 && static_cast<double>(chain.back().groups) < largest; ++step) {
    if (step % 2 == 0 && cp.labels() < energy.num_labels) {
      cp.increase_labels();
    } else if (!cp.iterate()) {
      break;
    }
    chain.push_back({LevelSpec{ColourPassingLevel{cp.labels(), cp.iterations()}}, cp.num_groups()});
  }
  std::size_t first_free = 0;
  for (const double fraction : fractions) {
    if (first_free >= chain.size()) break;
    const auto misfit = [&](std::size_t k) {
      return std::abs(std::log(static_cast<double>(chain[k].groups) / (fraction * n)));
    };
    std::size_t best = first_free;
    for (std::size_t c = first_free; c < chain.size(); ++c) {
      if (misfit(c) < misfit(best)) best = c;
    }
    levels.push_back(chain[best].spec);
    first_free = best + 1;
  }
  return levels;
}

}  // namespace c2f
