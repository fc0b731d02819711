// Concept conformance of every shipped type, and a foreign type opting in through traits.

#include <catch2/catch.hpp>

#include <optional>
#include <vector>

#include "c2f/c2f.hpp"
#include "support/random_models.hpp"

using namespace c2f;

static_assert(Energy<PairwiseEnergy>);
static_assert(ReducibleEnergy<PairwiseEnergy>);
static_assert(Partition<DensePartition>);
static_assert(AnytimeSolver<IcmSolver, PairwiseEnergy>);
static_assert(ReleasingSolver<ExpansionSolver<>>);  // its graphs go before the original level
static_assert(!ReleasingSolver<IcmSolver>);
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

// A foreign partition type (vertical stripes, members kept per stripe) made a Partition by
// specialising partition_traits, and a provider that hands it out.
namespace foreign {
struct Stripes {
  Stripes(std::size_t grid_width, std::size_t grid_height, std::size_t stripe)
      : width(grid_width), stripe_width(stripe), members((grid_width + stripe - 1) / stripe) {
    for (std::size_t v = 0; v < grid_width * grid_height; ++v)
      members[(v % grid_width) / stripe].push_back(static_cast<VariableIndex>(v));
  }
  std::size_t width, stripe_width;
  std::vector<std::vector<VariableIndex>> members;
};

struct StripeProvider {
  std::vector<Stripes> levels;
  std::size_t next_level = 0;
  std::optional<Stripes> next(const PairwiseEnergy&) {
    if (next_level == levels.size()) return std::nullopt;
    return levels[next_level++];
  }
};
}  // namespace foreign

template <>
struct c2f::partition_traits<foreign::Stripes> {
  static std::size_t num_variables(const foreign::Stripes& s) {
    std::size_t n = 0;
    for (const auto& stripe : s.members) n += stripe.size();
    return n;
  }
  static std::size_t num_groups(const foreign::Stripes& s) { return s.members.size(); }
  static std::size_t group_of(const foreign::Stripes& s, std::size_t v) {
    return (v % s.width) / s.stripe_width;
  }
  static std::span<const VariableIndex> members(const foreign::Stripes& s, std::size_t g) {
    return s.members[g];
  }
};
static_assert(Partition<foreign::Stripes>);
static_assert(PartitionProvider<foreign::StripeProvider, PairwiseEnergy>);

TEST_CASE("the driver takes levels of a foreign partition type through its traits",
          "[concepts][driver]") {
  test::Rng rng(4);
  const PairwiseEnergy energy = test::random_grid_energy(rng, 12, 6, 4);
  const foreign::Stripes halves(12, 6, 6), quarters(12, 6, 3);
  CHECK(to_dense_partition(quarters).num_groups() == 4);
  CHECK(to_dense_partition(quarters).members(1)[0] == 3);
  CHECK(to_dense_partition(quarters).is_refinement_of(to_dense_partition(halves)));

  auto run = [&](auto& provider) {
    std::vector<double> energies;
    ExpansionSolver<> solver;
    const Summary summary =
        coarse_to_fine(energy, provider, solver, Options{}, [&](const StepEvent& event) {
          energies.push_back(event.energy);
          return ObserverDecision::continue_run;
        });
    CHECK(summary.levels.size() == 3);
    CHECK(summary.energy == energy.evaluate(summary.labeling));
    return energies;
  };
  foreign::StripeProvider stripes{{halves, quarters}};
  PartitionList dense({to_dense_partition(halves), to_dense_partition(quarters)});
  CHECK(run(stripes) == run(dense));
}

TEST_CASE("reduce and the transfers read a foreign partition as its dense copy",
          "[concepts][lift]") {
  test::Rng rng(5);
  const PairwiseEnergy energy = test::random_grid_energy(rng, 12, 6, 4);
  const foreign::Stripes halves(12, 6, 6), quarters(12, 6, 3);
  const DensePartition dense_halves = to_dense_partition(halves);
  const DensePartition dense_quarters = to_dense_partition(quarters);
  static_assert(ReducibleEnergy<PairwiseEnergy, foreign::Stripes>);
  CHECK(refines(quarters, halves));
  CHECK_FALSE(refines(halves, quarters));
  CHECK(refines(quarters, dense_halves));

  const PairwiseEnergy reduced = reduce(energy, quarters);
  const PairwiseEnergy reduced_dense = reduce(energy, dense_quarters);
  REQUIRE(reduced.num_variables() == 4);
  const Labeling on_quarters{2, 0, 3, 1};
  CHECK(reduced.evaluate(on_quarters) == reduced_dense.evaluate(on_quarters));
  CHECK(expand(on_quarters, quarters) == expand(on_quarters, dense_quarters));

  const Labeling on_halves{1, 3};
  CHECK(transfer_labels(on_halves, halves, quarters) ==
        transfer_labels(on_halves, dense_halves, dense_quarters));
  CHECK(transfer_labels_by_majority(on_quarters, quarters, halves) ==
        transfer_labels_by_majority(on_quarters, dense_quarters, dense_halves));
  CHECK_THROWS_WITH(transfer_labels(on_quarters, quarters, halves),
                    Catch::Contains("does not refine"));
}

namespace foreign {
/// A partition whose group_of answers outside [0, num_groups): a broken foreign type.
struct OutOfRange {
  std::size_t n;
};
}  // namespace foreign

template <>
struct c2f::partition_traits<foreign::OutOfRange> {
  static std::size_t num_variables(const foreign::OutOfRange& p) { return p.n; }
  static std::size_t num_groups(const foreign::OutOfRange&) { return 1; }
  static std::size_t group_of(const foreign::OutOfRange&, std::size_t v) { return v; }
  static std::span<const VariableIndex> members(const foreign::OutOfRange&, std::size_t) {
    return {};
  }
};

TEST_CASE("a foreign partition with a group id out of range is refused by name",
          "[concepts][lift]") {
  test::Rng rng(6);
  const PairwiseEnergy energy = test::random_grid_energy(rng, 3, 1, 2);
  CHECK_THROWS_WITH(reduce(energy, foreign::OutOfRange{3}),
                    Catch::Contains("variable 1 is in group 1, but there are 1 groups"));
}
