// Negative compile test: coarse_to_fine must reject a solver without step(). Built with
// C2F_COMPILE_FAIL_CONTROL the solver is complete and the file must compile (the control that
// shows the failure comes from the missing requirement alone).
#include "c2f/c2f.hpp"

struct IncompleteSolver {
  void bind(const c2f::PairwiseEnergy&, std::span<const c2f::Label> start) {
    x.assign(start.begin(), start.end());
  }
#ifdef C2F_COMPILE_FAIL_CONTROL
  double step() {
    return 0.0;
  }
#endif
  double energy() const {
    return 0.0;
  }
  std::span<const c2f::Label> labeling() const {
    return x;
  }
  c2f::Labeling x;
};

int main() {
  const c2f::PairwiseEnergy energy(1, 2, {0.0, 1.0}, {}, {});
  c2f::PartitionList flat;
  IncompleteSolver solver;
  return static_cast<int>(
             c2f::coarse_to_fine(energy, flat, solver, c2f::Options{}).labeling.size()) -
         1;
}
