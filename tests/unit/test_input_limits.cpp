// Inputs whose sizes would wrap around or not fit in memory get a clear error before anything
// is allocated.

#include <catch2/catch.hpp>

#include "c2f/vision/synthetic_problem.hpp"

TEST_CASE("the synthetic problem refuses sizes that would wrap or not fit", "[limits]") {
  c2f::vision::SyntheticSpec spec;
  spec.shape = {9223372036854775809ULL, 2};  // width x height wraps around in 64 bits
  CHECK_THROWS_WITH(c2f::vision::make_synthetic_problem(spec),
                    Catch::Contains("9223372036854775809x2 pixels with 16 labels is too large"));
  spec.shape = {65536, 65536};
  CHECK_THROWS_WITH(c2f::vision::make_synthetic_problem(spec), Catch::Contains("too large"));
  spec.shape = {64, 48};
  CHECK(c2f::vision::make_synthetic_problem(spec).energy.num_variables() == 64 * 48);
}
