#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "c2f/core/pairwise_term.hpp"

using namespace c2f;

TEST_CASE("pairwise terms have the documented costs", "[core][term]") {
  const PairwiseTerm potts = PairwiseTerm::potts();
  CHECK(potts.cost(2, 2) == 0.0);
  CHECK(potts.cost(0, 5) == 1.0);

  const PairwiseTerm linear = PairwiseTerm::truncated_linear(2.5);
  CHECK(linear.cost(3, 3) == 0.0);
  CHECK(linear.cost(3, 5) == 2.0);
  CHECK(linear.cost(5, 3) == 2.0);
  CHECK(linear.cost(0, 9) == 2.5);

  const PairwiseTerm step = PairwiseTerm::tsgo_step();
  CHECK(step.cost(4, 4) == 0.0);
  CHECK(step.cost(4, 5) == 1.0 / 6.0);
  CHECK(step.cost(5, 4) == 1.0 / 6.0);
  CHECK(step.cost(4, 6) == 1.0);
  CHECK(step.cost(0, 80) == 1.0);

  const PairwiseTerm table = PairwiseTerm::table(2, {0.0, 1.5, -2.0, 3.0});
  CHECK(table.cost(0, 1) == 1.5);
  CHECK(table.cost(1, 0) == -2.0);
  CHECK(table.cost(1, 1) == 3.0);
  CHECK_FALSE(table.is_symmetric());
  CHECK(PairwiseTerm::table(2, {0.0, 1.0, 1.0, 4.0}).is_symmetric());
  CHECK(step.is_symmetric());
}

TEST_CASE("term kinds round-trip through their names", "[core][term]") {
  for (TermKind kind :
       {TermKind::potts, TermKind::truncated_linear, TermKind::tsgo_step, TermKind::table}) {
    CHECK(term_kind_from_string(to_string(kind)) == kind);
  }
  CHECK_THROWS_WITH(term_kind_from_string("linear"),
                    Catch::Contains("unknown pairwise term kind 'linear'"));
}

TEST_CASE("invalid terms are rejected with a message naming the problem",
          "[core][term][validation]") {
  CHECK_THROWS_WITH(PairwiseTerm::truncated_linear(0.0), Catch::Contains("truncation"));
  CHECK_THROWS_WITH(PairwiseTerm::truncated_linear(std::nan("")), Catch::Contains("truncation"));
  CHECK_THROWS_WITH(PairwiseTerm::table(2, {0.0, 1.0, 2.0}),
                    Catch::Contains("expected num_labels^2 = 4"));
  CHECK_THROWS_WITH(PairwiseTerm::table(0, {}), Catch::Contains("num_labels must be >= 1"));
  CHECK_THROWS_WITH(
      PairwiseTerm::table(2, {0.0, std::numeric_limits<double>::infinity(), 1.0, 0.0}),
      Catch::Contains("cost(0, 1) is not finite"));
  CHECK_THROWS_WITH(PairwiseTerm::table(2, {0, 1, 1, 0}).validate_for(3, "edge term"),
                    Catch::Contains("edge term: table term has 2 labels, the energy has 3"));
  CHECK_NOTHROW(PairwiseTerm::potts().validate_for(7, "x"));
}
