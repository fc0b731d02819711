// Determinism: two runs of a tool with the same inputs and options write byte-identical
// outputs. Timings are the only exception, and they live only in the trace's time column and
// in the "<number> s" / "<number>s" figures of the summary and the printed report, which are
// masked before the comparison.

#include <catch2/catch.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "c2f/core/uai.hpp"
#include "support/random_models.hpp"
#include "support/run_tool.hpp"
#include "support/synthetic_segmentation.hpp"
#include "support/synthetic_stereo.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Text with every duration ("0.129s", "1.97434 s", "3.294e-05 s") replaced by "<t>s".
std::string without_durations(const std::string& text) {
  static const std::regex duration(R"([0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)? ?s\b)");
  return std::regex_replace(text, duration, "<t>s");
}

/// A trace without its first column (time_s).
std::string without_time_column(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, kept;
  while (std::getline(in, line)) kept += line.substr(line.find(',') + 1) + "\n";
  return kept;
}

/// A tool's printed report: durations masked, and the time column of printed trace rows
/// (lines that start with a number and a comma).
std::string printed_report(const std::string& output) {
  static const std::regex trace_row(R"(^[0-9.e+-]+,)");
  // Progress lines: one as each level starts, then one every 2 s of the run's clock, which a
  // slow run (a loaded machine) prints and a fast one does not. Only the first of a level stays.
  static const std::regex progress(R"(^[a-z0-9-]+: level ([0-9]+) \()");
  std::istringstream in(output);
  std::string line, kept;
  std::set<std::string> levels_started;
  while (std::getline(in, line)) {
    std::smatch level;
    if (std::regex_search(line, level, progress) && !levels_started.insert(level[1]).second)
      continue;
    kept += std::regex_replace(line, trace_row, "<t>,") + "\n";
  }
  return without_durations(kept);
}

/// Every file of an output folder, timings masked as the file kind calls for.
std::map<std::string, std::string> outputs(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const std::string bytes = read_bytes(entry.path());
    files[name] = name.starts_with("trace") ? without_time_column(bytes)
                  : name == "summary.txt"   ? without_durations(bytes)
                                            : bytes;
  }
  return files;
}

/// Text with the thread counts the tools report ("on 2 threads", "on 1 thread") masked.
std::string without_thread_counts(const std::string& text) {
  static const std::regex threads(R"(on [0-9]+ threads?\b)");
  return std::regex_replace(text, threads, "on <n> threads");
}

/// Runs `binary arguments extra[i] -o FOLDER` into two folders and checks that they hold the
/// same files with the same bytes (timings masked, and the thread counts when the runs' extra
/// arguments differ) and that the printed reports agree too.
void check_two_runs_agree(const std::string& binary, const std::string& arguments,
                          const fs::path& dir, const std::array<std::string, 2>& extra = {"", ""}) {
  const auto masked = [&](std::string text) {
    return extra[0] == extra[1] ? text : without_thread_counts(text);
  };
  std::string printed[2];
  for (int run = 0; run < 2; ++run) {
    const fs::path out = dir / ("run" + std::to_string(run));
    fs::remove_all(out);
    const auto r = c2f::test::run_tool(
        binary, arguments + " " + extra[static_cast<std::size_t>(run)] + " -o " + out.string());
    INFO(arguments << "\n" << r.output);
    REQUIRE(r.exit_code == 0);
    printed[run] = masked(printed_report(r.output));
  }
  auto first = outputs(dir / "run0"), second = outputs(dir / "run1");
  for (auto* files : {&first, &second}) {
    if (files->count("summary.txt") != 0) (*files)["summary.txt"] = masked((*files)["summary.txt"]);
    // The marker records each file's inode, which differs from run to run.
    if (files->count(".c2f-owner") != 0) {
      (*files)[".c2f-owner"] =
          std::regex_replace((*files)[".c2f-owner"], std::regex(" [0-9]+\n"), " INODE\n");
    }
  }
  INFO(arguments);
  REQUIRE(first.size() >= 3);
  CHECK(first.size() == second.size());
  for (const auto& [name, bytes] : first) {
    INFO(name);
    REQUIRE(second.count(name) == 1);
    CHECK(second.at(name) == bytes);
  }
  // The printed report also names the output folder, which differs between the two runs.
  CHECK(std::regex_replace(printed[0], std::regex("run0"), "run") ==
        std::regex_replace(printed[1], std::regex("run1"), "run"));
}

}  // namespace

TEST_CASE("durations and timed progress lines are masked, and nothing else", "[cli][determinism]") {
  CHECK(without_durations("solve 0.129s, in 1.97434 s, 3.294e-05 s off; 30 steps, bad>1 2.5%") ==
        "solve <t>s, in <t>s, <t>s off; 30 steps, bad>1 2.5%");
  CHECK(without_time_column("time_s,level\n0.5,0\n0.7,1\n") == "level\n0\n1\n");
  CHECK(printed_report("# trace\n0.25,0,1\nenergy 3, 0.5 s\n") ==
        "# trace\n<t>,0,1\nenergy 3, <t>s\n");
  CHECK(printed_report("c2f-stereo: level 0 (lifted) step 0 at 0.1 s\n"
                       "c2f-stereo: level 0 (lifted) step 9 at 2.1 s\n"
                       "c2f-stereo: level 1 (original) step 12 at 2.5 s\ndone\n") ==
        "c2f-stereo: level 0 (lifted) step 0 at <t>s\n"
        "c2f-stereo: level 1 (original) step 12 at <t>s\ndone\n");
}

TEST_CASE("c2f-stereo writes the same bytes twice", "[cli][determinism][stereo]") {
  const fs::path dir = fs::temp_directory_path() / "c2f-test-determinism-stereo";
  fs::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 11);
  const std::string inputs = (dir / "left.png").string() + " " + (dir / "right.png").string() +
                             " --gt " + (dir / "gt.png").string() + " --gt-divisor 4 --labels 10";
  check_two_runs_agree(C2F_STEREO_BINARY,
                       inputs + " --schedule paper --label-order random --save-partitions",
                       dir / "expansion");
  check_two_runs_agree(C2F_STEREO_BINARY, inputs + " --schedule regions --solver swap",
                       dir / "swap");
  check_two_runs_agree(C2F_STEREO_BINARY, inputs + " --schedule flat --solver lbp --max-steps 8",
                       dir / "lbp");
}

TEST_CASE("c2f-stereo writes the same bytes on one thread and on several",
          "[cli][determinism][stereo][threads]") {
  const fs::path dir = fs::temp_directory_path() / "c2f-test-determinism-threads";
  fs::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 96, 64, 2, 12, 5);
  const std::string inputs = (dir / "left.png").string() + " " + (dir / "right.png").string() +
                             " --gt " + (dir / "gt.png").string() + " --gt-divisor 4 --labels 20";
  check_two_runs_agree(C2F_STEREO_BINARY, inputs + " --schedule paper", dir / "paper",
                       {"--threads 1", "--threads 2"});
  check_two_runs_agree(C2F_STEREO_BINARY, inputs + " --schedule flat --max-steps 10", dir / "flat",
                       {"--threads 1", "--threads 3"});
  // Large enough for the solve's region moves (ExpansionOptions::regions): 4 bands of rows.
  const fs::path big = dir / "regions";
  c2f::test::write_synthetic_pair(big, 160, 120, 2, 12, 7);
  const std::string big_inputs = (big / "left.png").string() + " " + (big / "right.png").string() +
                                 " --gt " + (big / "gt.png").string() +
                                 " --gt-divisor 4 --labels 16 --regions 16";
  for (const std::string schedule : {"flat", "aggregated"}) {
    check_two_runs_agree(C2F_STEREO_BINARY, big_inputs + " --schedule " + schedule, big / schedule,
                         {"--threads 1", "--threads 3"});
    CHECK(read_bytes(big / schedule / "run1" / "summary.txt")
              .find("solve: moves by 4 regions on 2 threads") != std::string::npos);
  }
  // Loopy BP by bands of 4096 of the 19200 variables (LbpOptions' default layout): 5 bands.
  const std::string lbp_inputs = (big / "left.png").string() + " " + (big / "right.png").string() +
                                 " --gt " + (big / "gt.png").string() +
                                 " --gt-divisor 4 --labels 16";
  check_two_runs_agree(C2F_STEREO_BINARY,
                       lbp_inputs + " --schedule flat --solver lbp --max-steps 6", big / "lbp",
                       {"--threads 1", "--threads 3"});
  CHECK(read_bytes(big / "lbp" / "run1" / "summary.txt")
            .find("solve: BP messages by bands of 4096 variables on 3 threads") !=
        std::string::npos);
}

TEST_CASE("c2f-solve writes the same bytes on one thread and on several",
          "[cli][determinism][solve][threads]") {
  // A 140 x 120 grid model: 4 max-flow parts of at least 4096 variables, its whole moves'
  // graphs recycled and changed by parts (flat), and a coarse level before them (the default).
  const fs::path dir = fs::temp_directory_path() / "c2f-test-determinism-solve";
  fs::remove_all(dir);
  fs::create_directories(dir);
  c2f::test::Rng rng(23);
  const c2f::PairwiseEnergy energy = c2f::test::random_grid_energy(rng, 140, 120, 6);
  {
    std::ofstream out(dir / "grid.uai");
    c2f::write_uai(energy, out);
  }
  const std::string model = (dir / "grid.uai").string() + " --grid 140x120 -q";
  for (const std::string schedule : {"flat", "default"}) {
    const std::string flags = schedule == "flat" ? " --schedule flat" : "";
    check_two_runs_agree(C2F_SOLVE_BINARY, model + flags, dir / schedule,
                         {"--threads 1", "--threads 3"});
    CHECK(read_bytes(dir / schedule / "run1" / "summary.txt")
              .find("max-flow in 4 parts on 3 threads") != std::string::npos);
  }
}

TEST_CASE("c2f-segment writes the same bytes twice", "[cli][determinism][segment]") {
  const fs::path dir = fs::temp_directory_path() / "c2f-test-determinism-segment";
  fs::remove_all(dir);
  const auto files = c2f::test::write_synthetic_segmentation(dir, 40, 30, 6);
  const std::string inputs =
      files.image + " " + files.seeds + " --gt " + files.gt + " --classes 4 ";
  check_two_runs_agree(C2F_SEGMENT_BINARY, inputs + "--aux mm --schedule superpixels", dir / "mm");
  check_two_runs_agree(C2F_SEGMENT_BINARY, inputs + "--aux ceres --schedule flat", dir / "ceres");
  check_two_runs_agree(C2F_SEGMENT_BINARY,
                       inputs + "--aux greedy --start current --schedule paper --save-partitions",
                       dir / "greedy");
}

TEST_CASE("c2f-segment writes the same bytes on one thread and on several",
          "[cli][determinism][segment][threads]") {
  const fs::path dir = fs::temp_directory_path() / "c2f-test-determinism-segment-threads";
  fs::remove_all(dir);
  // 160x120 pixels: 8-connected edges give about 150k points for the edge classes' k-means.
  const auto files = c2f::test::write_synthetic_segmentation(dir, 160, 120, 4);
  const std::string inputs = files.image + " " + files.seeds + " --gt " + files.gt + " ";
  check_two_runs_agree(C2F_SEGMENT_BINARY, inputs + "--max-steps 20", dir / "plusplus",
                       {"--threads 1", "--threads 2"});
  check_two_runs_agree(C2F_SEGMENT_BINARY, inputs + "--kmeans reference --max-steps 20",
                       dir / "reference", {"--threads 1", "--threads 3"});
}

TEST_CASE("c2f-synthetic writes the same bytes twice", "[cli][determinism]") {
  const fs::path dir = fs::temp_directory_path() / "c2f-test-determinism-synthetic";
  fs::remove_all(dir);
  fs::create_directories(dir);
  check_two_runs_agree(C2F_SYNTHETIC_BINARY, "--width 48 --height 40 --blocks 8,4,2 --seed 3",
                       dir / "icm");
}
