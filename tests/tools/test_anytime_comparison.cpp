// The benchmarks' headline comparison (bench/support/anytime_comparison.hpp) on hand-made traces.

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "support/anytime_comparison.hpp"

using c2f::bench::AnytimeComparison;
using c2f::bench::compare_anytime;
using c2f::bench::TracePoint;

TEST_CASE("compare_anytime: time to reach flat's energy and errors at deadlines", "[bench]") {
  const std::vector<TracePoint> flat{{0.0, 10.0, 0.4}, {1.0, 8.0, 0.4}, {2.0, 7.0, 0.4}};
  const std::vector<TracePoint> run{{0.0, 9.0, 0.1}, {0.5, 7.0, 0.1}, {1.0, 6.0, 0.1}};
  const AnytimeComparison result = compare_anytime({flat, 7.0, 2.0}, {run, 6.0, 1.0});
  CHECK(result.reach_seconds == 0.5);  // the first step at or below 7
  CHECK(result.reach_ratio == 0.25);
  CHECK(result.flat_error == Approx(0.4));
  CHECK(result.run_error == Approx(0.1));

  // A run that never reaches flat's energy has no reach time.
  const std::vector<TracePoint> slow{{0.0, 9.0, 0.1}, {3.0, 7.5, 0.1}};
  const AnytimeComparison never = compare_anytime({flat, 7.0, 2.0}, {slow, 7.5, 3.0});
  CHECK(std::isnan(never.reach_seconds));
  CHECK(std::isnan(never.reach_ratio));

  // Errors are read at deadlines over the longer run: an error that drops at 1 s of 2 s is seen
  // both before and after, and the same seed gives the same deadlines.
  const std::vector<TracePoint> drop{{0.0, 10.0, 1.0}, {1.0, 7.0, 0.0}};
  const AnytimeComparison a = compare_anytime({drop, 7.0, 2.0}, {drop, 7.0, 2.0}, 5);
  CHECK(a.flat_error > 0.0);
  CHECK(a.flat_error < 1.0);
  CHECK(a.run_error == a.flat_error);
  CHECK(compare_anytime({drop, 7.0, 2.0}, {drop, 7.0, 2.0}, 5).flat_error == a.flat_error);
}
