// What every tool does before and after its work (run_tool's guard_process): closed standard
// descriptors never become output files, a file-size limit is an error naming the file, and a
// failed write to stdout is an error.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/run_tool.hpp"
#include "support/synthetic_stereo.hpp"

namespace fs = std::filesystem;

namespace {

/// `command` run by sh -c, so that its own redirections and limits apply to the tool alone;
/// the tool's stderr (and stdout, unless redirected) come back in the result.
c2f::test::ToolResult run_shell(const std::string& command) {
  return c2f::test::run_tool("sh", "-c '" + command + "'");
}

std::string stereo_arguments(const fs::path& dir) {
  return (dir / "left.png").string() + " " + (dir / "right.png").string() + " -o " +
         (dir / "out").string() + " --labels 8";
}

}  // namespace

TEST_CASE("a tool whose stdout fails to write says so and exits 1", "[cli][guards]") {
  const auto r =
      run_shell(std::string(C2F_SYNTHETIC_BINARY) + " --width 40 --height 30 > /dev/full");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("c2f-synthetic: error: writing standard output failed"));
}

TEST_CASE("a tool started with stderr closed keeps its progress out of its files",
          "[cli][guards]") {
  const auto dir = fs::temp_directory_path() / "c2f-test-guards-closed-stderr";
  fs::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 5);
  // Without -q the tool prints progress on stderr; with descriptor 2 closed, the first file it
  // opened would otherwise have become stderr.
  const auto r = run_shell(std::string(C2F_STEREO_BINARY) + " " + stereo_arguments(dir) + " 2>&-");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (const char* name : {"trace.csv", "summary.txt"}) {
    std::ifstream file(dir / "out" / name);
    const std::string text((std::istreambuf_iterator<char>(file)), {});
    CHECK_THAT(text, !Catch::Contains("c2f-stereo:"));
  }
}

TEST_CASE("a file-size limit is an error naming the file, not a silent death", "[cli][guards]") {
  const auto dir = fs::temp_directory_path() / "c2f-test-guards-file-size";
  fs::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 5);
  // ulimit -f counts 512-byte blocks in POSIX sh: 2 blocks is too small for the outputs.
  const auto r = run_shell("ulimit -f 2; exec " + std::string(C2F_STEREO_BINARY) + " " +
                           stereo_arguments(dir) + " -q");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("c2f-stereo: error:") && Catch::Contains(".") &&
                           !Catch::Contains("File size limit"));
  CHECK_FALSE(fs::exists(dir / "out" / "summary.txt"));  // nothing landed
}
