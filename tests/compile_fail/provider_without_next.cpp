// Negative compile test: coarse_to_fine must reject a partition provider whose next() does not
// return std::optional<DensePartition>. C2F_COMPILE_FAIL_CONTROL fixes the return type.
#include "c2f/c2f.hpp"

struct IncompleteProvider {
#ifdef C2F_COMPILE_FAIL_CONTROL
  std::optional<c2f::DensePartition> next(const c2f::PairwiseEnergy&) {
    return std::nullopt;
  }
#else
  c2f::DensePartition next(const c2f::PairwiseEnergy& e) {
    return c2f::DensePartition::identity(e.num_variables());
  }
#endif
};

int main() {
  const c2f::PairwiseEnergy energy(1, 2, {0.0, 1.0}, {}, {});
  IncompleteProvider provider;
  c2f::IcmSolver solver;
  return static_cast<int>(
             c2f::coarse_to_fine(energy, provider, solver, c2f::Options{}).labeling.size()) -
         1;
}
