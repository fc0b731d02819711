// Inputs whose sizes would wrap around or not fit in memory get a clear error before anything
// is allocated; loaders refuse malformed and trailing data with a message naming the input.

#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <string>

#include "c2f/support/memory_need.hpp"
#include "c2f/vision/stereo/disparity_io.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"
#include "c2f/vision/synthetic_problem.hpp"

TEST_CASE("the synthetic problem refuses sizes that would wrap or not fit", "[limits]") {
  c2f::vision::SyntheticSpec spec;
  spec.shape = {9223372036854775809ULL, 2};  // width x height wraps around in 64 bits
  CHECK_THROWS_WITH(c2f::vision::make_synthetic_problem(spec),
                    Catch::Contains("9223372036854775809x2 pixels: each side must be at most"));
  spec.shape = {65536, 65536};
  CHECK_THROWS_WITH(c2f::vision::make_synthetic_problem(spec),
                    Catch::Contains("65536x65536 pixels with 16 labels needs 832.0 GiB") &&
                        Catch::Contains("this machine has available"));
  spec.shape = {64, 48};
  CHECK(c2f::vision::make_synthetic_problem(spec).energy.num_variables() == 64 * 48);
}

TEST_CASE("sizes are multiplied without wrapping and memory needs are checked", "[limits]") {
  using c2f::checked_product;
  CHECK(checked_product({3, 5, 7}) == std::size_t{105});
  CHECK(checked_product({}) == std::size_t{1});
  CHECK(c2f::checked_sum({3, 5, 7}) == std::size_t{15});
  CHECK(c2f::checked_sum({}) == std::size_t{0});
  CHECK_FALSE(c2f::checked_sum({std::numeric_limits<std::size_t>::max(), 1}).has_value());
  CHECK(checked_product({0, std::numeric_limits<std::size_t>::max(), 2}) == std::size_t{0});
  CHECK_FALSE(checked_product({std::size_t{1} << 32, std::size_t{1} << 32}).has_value());
  CHECK(c2f::format_bytes(512) == "512 bytes");
  CHECK(c2f::format_bytes(1.5 * (1 << 30)) == "1.5 GiB");
  const auto available = c2f::available_memory_bytes();
  REQUIRE(available.has_value());
  CHECK_NOTHROW(c2f::require_memory("a small problem", std::size_t{1} << 20));
  CHECK_THROWS_WITH(
      c2f::require_memory("a huge problem", *available + (std::size_t{1} << 30)),
      Catch::StartsWith("a huge problem needs ") && Catch::Contains("this machine has available"));
  CHECK_THROWS_WITH(c2f::require_memory("an overflowing problem", std::nullopt),
                    Catch::Contains("needs more than 16 EiB"));
  // The TSGO estimate grows with pixels x labels and overflows into "unknown", not a wrap.
  const auto teddy = c2f::vision::tsgo_memory_estimate(450, 375, 85, 2);
  REQUIRE(teddy.has_value());
  CHECK(*teddy == 450u * 375u * (85u * 4u + 512u + 640u) + 2u * 4096u * 64u);
  CHECK_FALSE(c2f::vision::tsgo_memory_estimate(std::size_t{1} << 40, std::size_t{1} << 30, 256)
                  .has_value());
}

namespace {

std::string pfm(const std::string& header, std::size_t floats) {
  std::string bytes = header;
  const float value = 1.5F;
  for (std::size_t i = 0; i < floats; ++i)
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
  return bytes;
}

}  // namespace

TEST_CASE("PFM parsing is strict: header, sizes, scale and exact data length", "[limits][io]") {
  using c2f::vision::parse_pfm;
  const cv::Mat good = parse_pfm(pfm("Pf\n3 2\n-1\n", 6), "good.pfm");
  CHECK(good.cols == 3);
  CHECK(good.rows == 2);
  CHECK(good.at<float>(1, 2) == 1.5F);
  CHECK_THROWS_WITH(parse_pfm(pfm("PF\n3 2\n-1\n", 18), "colour.pfm"),
                    Catch::Contains("'colour.pfm' is not a single-channel PFM file: expected the "
                                    "header 'Pf'"));
  CHECK_THROWS_WITH(
      parse_pfm(pfm("Pf\n3x 2\n-1\n", 6), "w.pfm"),
      Catch::Contains("expected a width and a height in [1, 65536], got '3x' and '2'"));
  CHECK_THROWS_WITH(parse_pfm(pfm("Pf\n1099511627776 1099511627776\n-1\n", 6), "huge.pfm"),
                    Catch::Contains("width and a height in [1, 65536]"));
  CHECK_THROWS_WITH(parse_pfm(pfm("Pf\n3 2\nnan\n", 6), "scale.pfm"),
                    Catch::Contains("expected a finite non-zero scale, got 'nan'"));
  CHECK_THROWS_WITH(parse_pfm(pfm("Pf\n3 2\n-1\n", 5), "short.pfm"),
                    Catch::Contains("'short.pfm' holds 20 bytes of data after its header, "
                                    "expected 24 (3x2 floats)"));
  CHECK_THROWS_WITH(parse_pfm(pfm("Pf\n3 2\n-1\n", 7), "long.pfm"),
                    Catch::Contains("holds 28 bytes"));
  CHECK_THROWS_WITH(parse_pfm("Pf\n3 2\n-1", "cut.pfm"),
                    Catch::Contains("no data after the header"));
  CHECK_THROWS_WITH(parse_pfm("", "empty.pfm"), Catch::Contains("expected the header 'Pf'"));
}
