#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "c2f/core/pairwise_energy.hpp"
#include "support/random_models.hpp"

using namespace c2f;

namespace {
// Three variables, two labels, a chain 0-1 (Potts, weight 2) and 1-2 (table, weight 0.5).
PairwiseEnergy chain() {
  return PairwiseEnergy(3, 2, {1.0, 0.0, 0.0, 3.0, 2.0, 2.5},
                        {PairwiseTerm::potts(), PairwiseTerm::table(2, {0.0, 4.0, 1.0, 0.0})},
                        {Edge{0, 1, 2.0, 0}, Edge{1, 2, 0.5, 1}});
}
}  // namespace

TEST_CASE("evaluate sums unaries and weighted pairwise costs", "[core][energy]") {
  const PairwiseEnergy e = chain();
  CHECK(e.num_variables() == 3);
  CHECK(e.num_labels() == 2);
  CHECK(e.unary(1, 1) == 3.0);
  // x = (0, 0, 1): 1 + 0 + 2.5 + 2*0 + 0.5*4 = 5.5
  CHECK(e.evaluate(Labeling{0, 0, 1}) == 5.5);
  // x = (1, 0, 0): 0 + 0 + 2 + 2*1 + 0.5*0 = 4
  CHECK(e.evaluate(Labeling{1, 0, 0}) == 4.0);
  // x = (0, 1, 0): orientation matters for the table: cost(1, 0) = 1
  CHECK(e.evaluate(Labeling{0, 1, 0}) == 1.0 + 3.0 + 2.0 + 2.0 + 0.5);
}

TEST_CASE("evaluate_unchecked on threads gives the serial sum's bits", "[core][energy]") {
  c2f::test::Rng rng(71);
  // 110 x 90 = 9900 variables and about 19600 edges: several chunks of each.
  const PairwiseEnergy energy = c2f::test::random_grid_energy(rng, 110, 90, 5);
  std::vector<Label> x(energy.num_variables());
  for (Label& l : x) l = std::uniform_int_distribution<Label>(0, 4)(rng);
  const double serial = energy.evaluate_unchecked(x);
  for (const int threads : {1, 2, 3, 0}) CHECK(energy.evaluate_unchecked(x, threads) == serial);
  CHECK(serial == Approx(energy.evaluate(x)));
}

TEST_CASE("evaluate rejects labelings that do not fit the energy", "[core][energy][validation]") {
  const PairwiseEnergy e = chain();
  CHECK_THROWS_WITH(e.evaluate(Labeling{0, 0}),
                    Catch::Contains("labeling: has 2 entries, expected num_variables = 3"));
  CHECK_THROWS_WITH(e.evaluate(Labeling{0, 2, 0}),
                    Catch::Contains("label 2 of variable 1 is out of range [0, 2)"));
  CHECK_THROWS_WITH(e.evaluate(Labeling{-1, 0, 0}), Catch::Contains("label -1 of variable 0"));
}

TEST_CASE("PairwiseEnergy validates every field", "[core][energy][validation]") {
  const auto inf = std::numeric_limits<double>::infinity();
  const auto nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<PairwiseTerm> potts{PairwiseTerm::potts()};
  CHECK_THROWS_WITH(PairwiseEnergy(2, 0, {}, potts, {}),
                    Catch::Contains("num_labels must be >= 1"));
  CHECK_THROWS_WITH(
      PairwiseEnergy(2, 2, {0, 0, 0}, potts, {}),
      Catch::Contains("unaries has 3 entries, expected num_variables * num_labels = 4"));
  CHECK_THROWS_WITH(PairwiseEnergy(2, 2, {0, 0, nan, 0}, potts, {}),
                    Catch::Contains("unaries: cost of label 0 at variable 1 is not finite"));
  CHECK_THROWS_WITH(PairwiseEnergy(2, 2, {0, inf, 0, 0}, potts, {}),
                    Catch::Contains("cost of label 1 at variable 0 is not finite"));
  CHECK_THROWS_WITH(PairwiseEnergy(2, 2, {0, 0, 0, 0}, potts, {Edge{0, 2, 1.0, 0}}),
                    Catch::Contains("edges[0]: endpoint (0, 2) out of range"));
  CHECK_THROWS_WITH(
      PairwiseEnergy(2, 2, {0, 0, 0, 0}, potts, {Edge{0, 1, 1.0, 0}, Edge{1, 1, 1.0, 0}}),
      Catch::Contains("edges[1]: self-loop at variable 1"));
  CHECK_THROWS_WITH(PairwiseEnergy(2, 2, {0, 0, 0, 0}, potts, {Edge{0, 1, nan, 0}}),
                    Catch::Contains("edges[0]: weight is not finite"));
  CHECK_THROWS_WITH(PairwiseEnergy(2, 2, {0, 0, 0, 0}, potts, {Edge{0, 1, 1.0, 1}}),
                    Catch::Contains("edges[0]: term index 1 out of range, there are 1 terms"));
  CHECK_THROWS_WITH(
      PairwiseEnergy(2, 2, {0, 0, 0, 0}, {PairwiseTerm::table(3, std::vector<double>(9, 0.0))}, {}),
      Catch::Contains("terms[0]: table term has 3 labels, the energy has 2"));
}

TEST_CASE("float unaries: the energy is what the stored float costs define",
          "[core][energy][float]") {
  // Costs that float does not hold exactly: the float energy is the double energy of the
  // float-rounded costs, summed in double.
  const std::vector<double> exact{0.1, 0.7, 1.0 / 3.0, 2.2, 1e-9, 5.0};
  const FloatValues stored(exact.begin(), exact.end());
  const std::vector<double> rounded(stored.begin(), stored.end());
  const std::vector<PairwiseTerm> terms{PairwiseTerm::potts()};
  const std::vector<Edge> edges{Edge{0, 1, 0.3, 0}, Edge{1, 2, 1.5, 0}};
  const PairwiseEnergy single = PairwiseEnergy::with_float_unaries(3, 2, stored, terms, edges);
  const PairwiseEnergy twin(3, 2, rounded, terms, edges);
  CHECK(single.single_precision());
  CHECK_FALSE(twin.single_precision());
  CHECK(single.unaries().single_precision());
  CHECK(single.unaries().bytes() * 2 == twin.unaries().bytes());
  CHECK(single.unaries().to_doubles() == rounded);
  for (std::size_t v = 0; v < 3; ++v) {
    for (Label l = 0; l < 2; ++l) {
      CHECK(single.unary(v, l) == rounded[v * 2 + static_cast<std::size_t>(l)]);
      CHECK(single.unaries().row(v)[static_cast<std::size_t>(l)] == single.unary(v, l));
      CHECK(single.unaries()(v, l) == single.unary(v, l));
    }
  }
  CHECK(single.unary(0, 0) != exact[0]);  // it is stored rounded
  for (const Labeling& x : {Labeling{0, 0, 0}, Labeling{1, 0, 1}, Labeling{0, 1, 1}}) {
    CHECK(single.evaluate(x) == twin.evaluate(x));
  }
  const auto nan = std::numeric_limits<float>::quiet_NaN();
  CHECK_THROWS_WITH(PairwiseEnergy::with_float_unaries(2, 2, {0, 0, 0, nan}, terms, {}),
                    Catch::Contains("unaries: cost of label 1 at variable 1 is not finite"));
  CHECK_THROWS_WITH(PairwiseEnergy::with_float_unaries(2, 2, {0, 0, 0}, terms, {}),
                    Catch::Contains("unaries has 3 entries"));
}

TEST_CASE("the first non-finite unary is named, wherever it is", "[core][energy][validation]") {
  // 1500 variables x 3 labels: the costs are scanned in chunks of 1024, so these land in the
  // first, a middle and the last chunk, in double and in float.
  const std::vector<PairwiseTerm> terms{PairwiseTerm::potts()};
  const std::size_t variables = 1500;
  for (const std::size_t bad : {std::size_t{5}, std::size_t{2049}, std::size_t{4499}}) {
    for (const double value :
         {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}) {
      std::vector<double> costs(variables * 3, 1.0);
      costs[bad] = value;
      if (bad + 7 < costs.size()) costs[bad + 7] = value;  // a later one is not the one named
      const std::string named = "cost of label " + std::to_string(bad % 3) + " at variable " +
                                std::to_string(bad / 3) + " is not finite";
      INFO("index " << bad << ", value " << value);
      CHECK_THROWS_WITH(PairwiseEnergy(variables, 3, costs, terms, {}), Catch::Contains(named));
      const FloatValues stored(costs.begin(), costs.end());
      CHECK_THROWS_WITH(PairwiseEnergy::with_float_unaries(variables, 3, stored, terms, {}),
                        Catch::Contains(named));
    }
  }
  CHECK_NOTHROW(PairwiseEnergy(variables, 3, std::vector<double>(variables * 3, 1e300), terms, {}));
}
