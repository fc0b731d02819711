// Negative compile test: a type without evaluate() is not an Energy, so generic code that
// requires one must not compile. C2F_COMPILE_FAIL_CONTROL adds the member: then it compiles.
#include "c2f/c2f.hpp"

struct IncompleteEnergy {
  std::size_t num_variables() const { return 2; }
  int num_labels() const { return 2; }
  double unary(std::size_t, c2f::Label l) const { return l; }
#ifdef C2F_COMPILE_FAIL_CONTROL
  double evaluate(std::span<const c2f::Label>) const {
    return 0.0;
  }
#endif
};

int main() {
  return static_cast<int>(
             c2f::initial_labeling(IncompleteEnergy{}, c2f::InitialLabeling::zero).size()) -
         2;
}
