// c2f-segment's command line: errors name the input and give exit code 2; runs write their
// outputs, flat and coarse to fine, for every method.

#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <utility>

#include "c2f/run/segmentation_run.hpp"
#include "support/run_tool.hpp"
#include "support/synthetic_segmentation.hpp"

namespace {

c2f::test::ToolResult run(const std::string& arguments) {
  return c2f::test::run_tool(C2F_SEGMENT_BINARY, arguments);
}

}  // namespace

TEST_CASE("c2f-segment writes labels, overlay, trace and summary", "[segment][cli]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segment-run";
  std::filesystem::remove_all(dir);
  const auto files = c2f::test::write_synthetic_segmentation(dir, 40, 30, 4);
  for (const char* flags :
       {"--method potts --schedule flat", "--aux mm --schedule paper",
        "--aux greedy --start current --schedule paper-cc --save-partitions",
        "--aux ceres --schedule flat --gmm-seed 3 --edge-seed 4 --kmeans reference"}) {
    const std::string out = (dir / "out").string();
    std::filesystem::remove_all(out);
    const c2f::test::ToolResult r = run(files.image + " " + files.seeds + " --gt " + files.gt +
                                        " -o " + out + " -q --classes 4 " + flags);
    INFO(flags << "\n" << r.output);
    REQUIRE(r.exit_code == 0);
    for (const char* file : {"labels.png", "overlay.png", "trace.csv", "summary.txt"})
      CHECK(std::filesystem::exists(dir / "out" / file));
    std::ifstream summary(dir / "out" / "summary.txt");
    const std::string text((std::istreambuf_iterator<char>(summary)), {});
    CHECK_THAT(text, Catch::Contains("pixel error: ") && Catch::Contains("cooperative-cut energy"));
    const bool reseeded = std::string(flags).find("--gmm-seed 3") != std::string::npos;
    CHECK_THAT(text,
               Catch::Contains(reseeded ? "k-means sample start, batch and online phases, seeds "
                                          "3 (GMMs) and 4 (edge classes)\n"
                                        : "k-means plusplus start, batch rounds only, seeds 27 "
                                          "(GMMs) and 27 (edge classes)\n"));
  }
  CHECK(std::filesystem::exists(dir / "out" / "partition-level0.png") == false);  // last run: flat
}

TEST_CASE("c2f-segment's flags default to the library's segmentation defaults",
          "[segment][cli][defaults]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segment-defaults";
  std::filesystem::remove_all(dir);
  const auto files = c2f::test::write_synthetic_segmentation(dir, 80, 60, 3);
  const c2f::vision::SegmentationDefaults defaults = c2f::vision::segmentation_defaults();
  const auto summary_of = [&](const std::string& flags) {
    const std::string out = (dir / "out").string();
    std::filesystem::remove_all(out);
    const c2f::test::ToolResult r =
        run(files.image + " " + files.seeds + " -o " + out + " -q --classes 4 " + flags);
    INFO(flags << "\n" << r.output);
    REQUIRE(r.exit_code == 0);
    std::ifstream summary(dir / "out" / "summary.txt");
    return std::string((std::istreambuf_iterator<char>(summary)), {});
  };
  const std::string plain = summary_of("");
  const std::string near = "near moves of radius " + std::to_string(defaults.mm_near_radius) +
                           " from their label (whole moves where they stall)";
  CHECK_THAT(plain, Catch::Contains("method " + std::string(to_string(defaults.method)) +
                                    ", auxiliary variables " +
                                    std::string(to_string(defaults.strategy))) &&
                        Catch::Contains(near));
  std::ostringstream parameters;
  parameters << "lambda " << defaults.parameters.lambda << ", theta " << defaults.parameters.theta
             << ", alpha " << defaults.parameters.alpha << ",";
  CHECK_THAT(plain, Catch::Contains(parameters.str()));
  // Naming every default gives the same run: the same energy, step for step.
  const std::string named = summary_of("--schedule " + defaults.schedule + " --aux " +
                                       std::string(to_string(defaults.strategy)) +
                                       " --near-radius " + std::to_string(defaults.mm_near_radius));
  const std::regex energy_line(R"(final energy \S+ after \d+ steps)");
  std::smatch plain_energy, named_energy;
  REQUIRE(std::regex_search(plain, plain_energy, energy_line));
  REQUIRE(std::regex_search(named, named_energy, energy_line));
  CHECK(plain_energy.str() == named_energy.str());
  // Greedy makes whole moves unless --near-radius is named; 0 is whole moves with mm.
  CHECK_THAT(summary_of("--aux greedy --max-steps 3"),
             Catch::Contains("solve: every move over every variable"));
  CHECK_THAT(summary_of("--aux greedy --start current --near-radius 2 --max-steps 3"),
             Catch::Contains("near moves of radius 2 from their label"));
  CHECK_THAT(summary_of("--near-radius 0 --max-steps 3"),
             Catch::Contains("solve: every move over every variable"));
  const std::string out = (dir / "bad").string();
  for (const auto& [flags, message] :
       {std::pair{"--near-radius -1", "--near-radius: expected an integer in [0, 1000000]"},
        std::pair{"--near-radius wide", "--near-radius: expected an integer in"},
        std::pair{"--method potts --near-radius 2", "--near-radius: applies to --method coop"}}) {
    const c2f::test::ToolResult r =
        run(files.image + " " + files.seeds + " -o " + out + " -q " + flags);
    INFO(flags << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains(message));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("c2f-segment stopped by SIGTERM writes the best labeling so far and exits 143",
          "[segment][cli][interrupt]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segment-interrupt";
  std::filesystem::remove_all(dir);
  // Large enough, with the slow greedy strategy, that the run is still going at the signal.
  const auto files = c2f::test::write_synthetic_segmentation(dir, 400, 300, 4);
  const std::string out = (dir / "out").string();
  const auto r = c2f::test::run_tool_interrupted(
      C2F_SEGMENT_BINARY,
      files.image + " " + files.seeds + " -o " + out + " --aux greedy --schedule flat", 3.0,
      SIGTERM);
  INFO(r.output);
  CHECK(r.exit_code == 143);
  CHECK_THAT(r.output, Catch::Contains("interrupted by SIGTERM"));
  std::ifstream summary(out + "/summary.txt");
  const std::string text((std::istreambuf_iterator<char>(summary)), {});
  CHECK_THAT(text, Catch::Contains("interrupted by SIGTERM after"));
  CHECK(std::filesystem::exists(out + "/labels.png"));
}

TEST_CASE("c2f-segment's cooperative run stays within its memory budget, or says what it needs",
          "[segment][cli][memory]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segment-memory";
  std::filesystem::remove_all(dir);
  const auto files = c2f::test::write_synthetic_segmentation(dir, 240, 180, 4);
  const std::string inputs = files.image + " " + files.seeds + " -q --classes 4 --threads 1";
  // 0.1 GiB holds the data preparation but not the run's floor: refused, with what it needs.
  const c2f::test::ToolResult refused =
      run(inputs + " -o " + (dir / "refused").string() + " --memory 0.1");
  INFO(refused.output);
  CHECK(refused.exit_code != 0);
  std::smatch need;
  const std::regex needs(
      "the cooperative energy needs ([0-9.]+) MiB, more than the run's "
      "memory budget of 102.4 MiB \\(--memory 0.1\\)");
  REQUIRE(std::regex_search(refused.output, need, needs));
  CHECK_FALSE(std::filesystem::exists(dir / "refused" / "labels.png"));
  // A budget 32 MiB above the floor: the run's peak stays within it.
  const double budget_mib = std::stod(need[1].str()) + 32.0;
  const std::string memory = std::to_string(budget_mib / 1024.0);
  const c2f::test::ToolResult r = c2f::test::run_tool_measured(
      C2F_SEGMENT_BINARY, inputs + " -o " + (dir / "fits").string() + " --memory " + memory);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(std::filesystem::exists(dir / "fits" / "labels.png"));
#if defined(__SANITIZE_ADDRESS__)
  // Resident sizes there include the sanitizer's shadow memory and quarantine.
  WARN("AddressSanitizer build: peak resident size " << r.peak_kib
                                                     << " KiB not compared with the budget");
#else
  CHECK(static_cast<double>(r.peak_kib) <= budget_mib * 1024.0);
#endif
}
