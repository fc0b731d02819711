// Concept conformance of every shipped type, and a foreign type opting in through traits.

#include <catch2/catch.hpp>

#include "c2f/c2f.hpp"

using namespace c2f;

static_assert(Energy<PairwiseEnergy>);
static_assert(ReducibleEnergy<PairwiseEnergy>);
static_assert(Partition<DensePartition>);
static_assert(AnytimeSolver<IcmSolver, PairwiseEnergy>);
static_assert(PartitionProvider<PartitionList, PairwiseEnergy>);
static_assert(PartitionProvider<BlockHierarchy, PairwiseEnergy>);

// Types missing a requirement are rejected.
struct NotAnEnergy {
  std::size_t num_variables() const { return 1; }
};
struct SolverWithoutStep {
  void bind(const PairwiseEnergy&, std::span<const Label>) {}
  double energy() const { return 0.0; }
  std::span<const Label> labeling() const { return {}; }
};
static_assert(!Energy<NotAnEnergy>);
static_assert(!Energy<int>);
static_assert(!AnytimeSolver<SolverWithoutStep, PairwiseEnergy>);
static_assert(!PartitionProvider<IcmSolver, PairwiseEnergy>);
static_assert(!Partition<PairwiseEnergy>);

// A foreign energy type whose members have other names, made an Energy by specialising traits.
namespace foreign {
struct Chain {
  int size;
  double cost(int, int label) const { return label; }
};
}  // namespace foreign

template <>
struct c2f::energy_traits<foreign::Chain> {
  static std::size_t num_variables(const foreign::Chain& c) {
    return static_cast<std::size_t>(c.size);
  }
  static int num_labels(const foreign::Chain&) { return 2; }
  static double unary(const foreign::Chain& c, std::size_t v, Label l) {
    return c.cost(static_cast<int>(v), l);
  }
  static double evaluate(const foreign::Chain& c, std::span<const Label> x) {
    double total = 0.0;
    for (std::size_t v = 0; v < x.size(); ++v) total += c.cost(static_cast<int>(v), x[v]);
    return total;
  }
};
static_assert(Energy<foreign::Chain>);

TEST_CASE("generic code works with a foreign energy through its traits", "[concepts]") {
  const foreign::Chain chain{3};
  CHECK(initial_labeling(chain, InitialLabeling::unary_argmin) == Labeling{0, 0, 0});
}
