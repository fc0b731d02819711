// c2f-synthetic's command line: a run writes both traces and the pictures; Ctrl-C stops the
// running solve at its next step and still writes everything (exit 130).

#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/run_tool.hpp"

namespace fs = std::filesystem;

TEST_CASE("c2f-synthetic stopped by SIGINT writes what it found and exits 130",
          "[synthetic][cli][interrupt]") {
  const fs::path out = fs::temp_directory_path() / "c2f-test-synthetic-interrupt";
  fs::remove_all(out);
  // Flat ICM on 600x600 pixels and 64 labels takes several seconds; the signal comes first.
  const auto r = c2f::test::run_tool_interrupted(
      C2F_SYNTHETIC_BINARY, "--width 600 --height 600 --labels 64 -o " + out.string(), 1.5, SIGINT);
  INFO(r.output);
  CHECK(r.exit_code == 130);
  CHECK_THAT(r.output, Catch::Contains("interrupted by SIGINT") &&
                           Catch::Contains("flat: energy") && Catch::Contains("c2f:  energy"));
  for (const char* name : {"trace-flat.csv", "trace-c2f.csv", "truth.pgm", "flat.pgm", "c2f.pgm"})
    CHECK(fs::exists(out / name));
  std::ifstream trace(out / "trace-flat.csv");
  const std::string text((std::istreambuf_iterator<char>(trace)), {});
  REQUIRE_FALSE(text.empty());
  CHECK(text.back() == '\n');  // whole rows only
}
