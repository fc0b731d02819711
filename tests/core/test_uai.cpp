#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

#include "c2f/core/uai.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

TEST_CASE("UAI round trips keep every energy difference", "[uai]") {
  Rng rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const int num_labels = 1 + trial % 4;
    const PairwiseEnergy energy = random_energy(rng, 2 + trial % 9, num_labels, 3 * (trial % 5));
    std::stringstream file;
    write_uai(energy, file);
    const PairwiseEnergy back = read_uai(file, "round-trip");
    REQUIRE(back.num_variables() == energy.num_variables());
    REQUIRE(back.num_labels() == num_labels);
    CHECK(back.edges().size() == energy.edges().size());
    // The file holds exp(-(cost - the factor's lowest cost)): energies come back shifted by
    // one constant, the same for every labeling.
    const Labeling reference = random_labeling(rng, energy.num_variables(), num_labels);
    const double offset = energy.evaluate(reference) - back.evaluate(reference);
    for (int sample = 0; sample < 10; ++sample) {
      const Labeling x = random_labeling(rng, energy.num_variables(), num_labels);
      CHECK(std::abs(back.evaluate(x) + offset - energy.evaluate(x)) <=
            1e-12 * std::max(1.0, std::abs(energy.evaluate(x))));
    }
  }
}

TEST_CASE("a hand-written UAI file reads as the energy it describes", "[uai]") {
  // Two binary variables: unaries (0.5, 0.25) on x0 and potential 1 on x1 given twice
  // (summed), and a pairwise factor that favours equal labels.
  std::istringstream file(R"(MARKOV
2
2 2
4
1 0
1 1
1 1
2 0 1

2
0.5 0.25
2
1 1
2
1 0.5
4
1 0.5
0.25 1
)");
  const PairwiseEnergy energy = read_uai(file, "hand.uai");
  CHECK(energy.num_variables() == 2);
  CHECK(energy.unary(0, 0) == Approx(-std::log(0.5)));
  CHECK(energy.unary(1, 1) == Approx(-std::log(0.5)));
  // x = (1, 0): -ln 0.25 - ln 1 - ln 1 - ln 0.25
  CHECK(energy.evaluate(Labeling{1, 0}) == Approx(-2 * std::log(0.25)));
  CHECK(energy.evaluate(Labeling{0, 1}) == Approx(-std::log(0.5) - std::log(0.5) - std::log(0.5)));
}

TEST_CASE("malformed UAI files give errors naming the problem", "[uai][validation]") {
  auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      (void)read_uai(in, "bad.uai");
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error_of("BAYES 1 2 0"),
             Catch::Contains("bad.uai: token 1: network type 'BAYES' is not supported"));
  CHECK_THAT(error_of("MARKOV 2 2 3 0"),
             Catch::Contains("variable 1 has cardinality 3, variable 0 has 2"));
  CHECK_THAT(error_of("MARKOV 2 2 2 1 3 0 1 1"), Catch::Contains("factor 0 has 3 variables"));
  CHECK_THAT(error_of("MARKOV 2 2 2 1 2 0 0"),
             Catch::Contains("factor 0 joins variable 0 to itself"));
  CHECK_THAT(error_of("MARKOV 2 2 2 1 1 5"),
             Catch::Contains("a variable of factor 0 5 is out of range"));
  CHECK_THAT(error_of("MARKOV 1 2 1 1 0 3 1 1 1"),
             Catch::Contains("factor 0 has 3 table entries, expected 2"));
  CHECK_THAT(error_of("MARKOV 1 2 1 1 0 2 1 0"), Catch::Contains("potential 0 is not > 0"));
  CHECK_THAT(error_of("MARKOV 1 2 1 1 0 2 1 x"),
             Catch::Contains("expected a potential of factor 0, got 'x'"));
  CHECK_THAT(error_of("MARKOV 1 2 1 1 0 2 1"), Catch::Contains("unexpected end of file"));
  CHECK_THROWS_WITH(read_uai_file("/nonexistent.uai"),
                    Catch::Contains("UAI file '/nonexistent.uai' does not exist"));
  CHECK_THAT(error_of("MARKOV 1 2 1 1 0 2 1 1 7"),
             Catch::Contains("unexpected '7' after the last table (trailing data)"));
  // A 50-byte file claiming 2^40 factors or entries: refused before any allocation.
  CHECK_THAT(error_of("MARKOV 1 2 1099511627776"),
             Catch::Contains("the number of factors 1099511627776 is more than the file's"));
  CHECK_THAT(error_of("MARKOV 2 1048576 1048576 1 2 0 1 1099511627776 1"),
             Catch::Contains("the table size of factor 0 1099511627776 is more than the file's"));
  std::string many_labels = "MARKOV 1100";
  for (int v = 0; v < 1100; ++v) many_labels += " 1048576";
  CHECK_THAT(error_of(many_labels + " 0"),
             Catch::Contains("1100 variables x 1048576 labels need more than 8 GiB"));
  const PairwiseEnergy spread(1, 2, {0.0, 1000.0}, {}, {});
  std::ostringstream out;
  CHECK_THROWS_WITH(write_uai(spread, out),
                    Catch::Contains("unary of variable 0: costs 0 and 1000 are too "
                                    "far apart"));
}

TEST_CASE("UAI keeps energy differences of costs far from zero", "[uai]") {
  // Costs of 1e6 (beyond exp's range on their own) with small spreads per factor.
  const PairwiseEnergy energy(2, 2, {1e6, 1e6 + 0.5, -3000.0, -2999.0},
                              {PairwiseTerm::table(2, {700.0, 701.0, 702.0, 700.25})},
                              {Edge{0, 1, 1.0, 0}});
  std::stringstream file;
  write_uai(energy, file);
  const PairwiseEnergy back = read_uai(file, "far.uai");
  const double base = energy.evaluate(Labeling{0, 0}) - back.evaluate(Labeling{0, 0});
  for (const Labeling& x : {Labeling{0, 1}, Labeling{1, 0}, Labeling{1, 1}})
    CHECK(back.evaluate(x) + base == Approx(energy.evaluate(x)).epsilon(1e-12));
}

TEST_CASE("MPE results round-trip and malformed ones are refused", "[uai]") {
  const Labeling labeling{2, 0, 1, 2};
  std::stringstream file;
  write_uai_mpe(labeling, file);
  CHECK(file.str() == "MPE\n4 2 0 1 2\n");
  CHECK(read_uai_mpe(file, "a.mpe", 4, 3) == labeling);
  std::istringstream two_solutions("MPE\n4 0 0 0 0\n-BEGIN-\n4 1 1 2 0\n");
  CHECK(read_uai_mpe(two_solutions, "b.mpe", 4, 3) == Labeling{1, 1, 2, 0});
  std::istringstream no_header("4 1 1 1 1");
  CHECK(read_uai_mpe(no_header, "c.mpe", 4, 3) == Labeling{1, 1, 1, 1});
  const auto refused = [](const std::string& text) {
    std::istringstream in(text);
    return read_uai_mpe(in, "bad.mpe", 4, 3);
  };
  CHECK_THROWS_WITH(
      refused("MPE\n3 0 0 0\n"),
      Catch::Contains("bad.mpe") && Catch::Contains("expected the number of variables 4, got '3'"));
  CHECK_THROWS_WITH(refused("MPE\n4 0 0 3 0\n"),
                    Catch::Contains("the label of variable 2 3 is out of range [0, 2]"));
  CHECK_THROWS_WITH(refused("MPE\n4 0 0 0\n"), Catch::Contains("unexpected end of file"));
  CHECK_THROWS_WITH(refused("MPE\n4 0 0 0 0 5\n"), Catch::Contains("trailing data"));
  CHECK_THROWS_WITH(refused("MPE\n4 0 x 0 0\n"), Catch::Contains("got 'x'"));
}

TEST_CASE("a UAI export is sized before it is written", "[uai][limits]") {
  Rng rng(12);
  const PairwiseEnergy small = random_grid_energy(rng, 5, 4, 3);
  std::ostringstream text;
  write_uai(small, text);
  // An upper estimate, and not a wild one.
  CHECK(uai_bytes_estimate(small) >= text.str().size());
  CHECK(uai_bytes_estimate(small) < 3 * text.str().size());

  // Two variables with a million labels: 10^12 potentials on the edge, about 24 TB, more than
  // any disk here has free; refused before a byte is written.
  const int labels = 1'000'000;
  const PairwiseEnergy huge(2, labels, std::vector<double>(2 * labels, 0.0),
                            {PairwiseTerm::potts()}, {Edge{0, 1, 1.0, 0}});
  const auto path = std::filesystem::temp_directory_path() / "c2f-test-huge.uai";
  std::filesystem::remove(path);
  CHECK_THROWS_WITH(write_uai_file(huge, path.string()),
                    Catch::Contains("c2f-test-huge.uai' needs about") &&
                        Catch::Contains("1000000^2 potentials on 1 edges") &&
                        Catch::Contains("GB free"));
  CHECK_FALSE(std::filesystem::exists(path));
}
