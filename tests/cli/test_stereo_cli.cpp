// c2f-stereo's command line: errors name the input and give exit code 2; a small run writes
// its outputs.

#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_tool.hpp"
#include "support/synthetic_stereo.hpp"

namespace {

c2f::test::ToolResult run(const std::string& arguments) {
  return c2f::test::run_tool(C2F_STEREO_BINARY, arguments);
}

/// The energies of the last level's rows of a trace.csv (time_s,level,step,energy,num_vars...),
/// in order.
std::vector<double> last_level_energies(const std::filesystem::path& trace_path) {
  std::ifstream trace(trace_path);
  std::string line;
  std::getline(trace, line);
  std::vector<double> energies;
  std::string last_level;
  while (std::getline(trace, line)) {
    const std::size_t level_at = line.find(',') + 1;
    const std::size_t step_at = line.find(',', level_at) + 1;
    const std::string level = line.substr(level_at, step_at - 1 - level_at);
    if (level != last_level) energies.clear();
    last_level = level;
    energies.push_back(std::stod(line.substr(line.find(',', step_at) + 1)));
  }
  return energies;
}

}  // namespace

TEST_CASE("c2f-stereo writes disparity maps, trace and summary", "[stereo][cli]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-run";
  std::filesystem::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 5);
  const c2f::test::ToolResult r =
      run((dir / "left.png").string() + " " + (dir / "right.png").string() + " -o " +
          (dir / "out").string() + " --labels 10 --gt " + (dir / "gt.png").string() +
          " --gt-divisor 4 --save-partitions --label-order frequency"
          " --plateau-tolerance 1e-4 -q");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (const char* file : {"disparity.pfm", "disparity.png", "disparity-colour.png", "error.png",
                           "trace.csv", "summary.txt", "partition-level0.png"}) {
    CHECK(std::filesystem::exists(dir / "out" / file));
  }
}

TEST_CASE("c2f-stereo with near moves descends and stops after three quiet sweeps",
          "[stereo][cli][near]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-near";
  std::filesystem::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 7);
  const int labels = 8;
  const auto r = run((dir / "left.png").string() + " " + (dir / "right.png").string() + " -o " +
                     (dir / "out").string() + " --labels " + std::to_string(labels) +
                     " --schedule flat --near-radius 2 --shift-moves=off -q");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::vector<double> energies = last_level_energies(dir / "out" / "trace.csv");
  REQUIRE(energies.size() > 3 * labels);
  CHECK(std::is_sorted(energies.rbegin(), energies.rend()));  // never increases
  CHECK(energies.back() < energies.front());
  // The default final plateau with near moves is three sweeps: the run ends after 3L steps
  // without decrease, not one sweep.
  const auto quiet = std::count(energies.begin(), energies.end(), energies.back()) - 1;
  CHECK(quiet == 3 * labels);
}

TEST_CASE("c2f-stereo makes near moves on the levels --near-levels names, and says so",
          "[stereo][cli][near]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-near-levels";
  std::filesystem::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 7);
  // summary.txt's second line and trace.csv without its times.
  auto solve = [&](const std::string& levels) {
    const auto out = dir / levels;
    const auto r = run(
        (dir / "left.png").string() + " " + (dir / "right.png").string() + " -o " + out.string() +
        " --labels 8 --schedule \"local:1,1/cc flat\" --near-radius 2 --shift-moves=off" +
        " --near-levels " + levels + " -q");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    std::ifstream summary(out / "summary.txt");
    std::string line;
    std::getline(summary, line);
    std::getline(summary, line);
    std::ifstream trace(out / "trace.csv");
    std::vector<std::string> rows;
    for (std::string row; std::getline(trace, row);)
      rows.push_back(row.substr(row.find(',') + 1));  // without time_s, which always differs
    return std::pair{line, rows};
  };
  const auto [original_line, original_trace] = solve("original");
  const auto [all_line, all_trace] = solve("all");
  CHECK_THAT(original_line, Catch::EndsWith("near moves of radius 2 on the original problem only"));
  CHECK_THAT(all_line, Catch::EndsWith("near moves of radius 2 on every level"));
  CHECK(original_trace.size() > 1);
  CHECK(original_trace != all_trace);  // the coarse level moves differently
}

TEST_CASE(
    "c2f-stereo with shift moves descends, ends after a quiet sweep of L + 2 steps, and "
    "says so",
    "[stereo][cli][shift]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-shift";
  std::filesystem::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 7);
  const int labels = 8;
  const auto r = run((dir / "left.png").string() + " " + (dir / "right.png").string() + " -o " +
                     (dir / "out").string() + " --labels " + std::to_string(labels) +
                     " --schedule \"local:1,1/cc flat\" --near-radius 0 --shift-moves -q");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::ifstream summary(dir / "out" / "summary.txt");
  std::string line;
  std::getline(summary, line);
  std::getline(summary, line);
  CHECK_THAT(line, Catch::EndsWith("shift moves on the original problem only"));
  // The original problem is the last level.
  const std::vector<double> energies = last_level_energies(dir / "out" / "trace.csv");
  REQUIRE(energies.size() > labels + 2);
  CHECK(std::is_sorted(energies.rbegin(), energies.rend()));  // never increases
  // The default final plateau is one sweep: L expansion moves and the two shift moves.
  const auto quiet = std::count(energies.begin(), energies.end(), energies.back()) - 1;
  CHECK(quiet == labels + 2);
}

TEST_CASE("c2f-stereo gives the same disparities on every max-flow backend", "[stereo][cli]") {
  // Integer-valued costs are not guaranteed here, so ties between minimum cuts could in
  // principle be broken differently; on this small scene all backends agree exactly.
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-maxflow";
  std::filesystem::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 9);
  auto solve = [&](const std::string& backend, const std::string& extra) {
    const std::string out = (dir / (extra.empty() ? backend : backend + "-shared")).string();
    const auto r = run((dir / "left.png").string() + " " + (dir / "right.png").string() + " -o " +
                       out + " --labels 8 --schedule flat -q --maxflow " + backend + extra);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return cv::imread(out + "/disparity.png", cv::IMREAD_UNCHANGED);
  };
  const cv::Mat boost = solve("boost", "");
  const cv::Mat dynamic = solve("dynamic", "");
  const cv::Mat shared = solve("dynamic", " --graph-memory 0");
  CHECK(cv::countNonZero(boost != dynamic) == 0);
  CHECK(cv::countNonZero(boost != shared) == 0);
}

TEST_CASE("c2f-stereo stopped by SIGINT writes the best labeling so far and exits 130",
          "[stereo][cli][interrupt]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-interrupt";
  std::filesystem::remove_all(dir);
  // Large enough that the run is still going when the signal arrives (seconds of whole moves;
  // with the stereo defaults' near and shift moves it can converge first).
  c2f::test::write_synthetic_pair(dir, 480, 360, 8, 40, 11);
  const std::string out = (dir / "out").string();
  const auto r = c2f::test::run_tool_interrupted(
      C2F_STEREO_BINARY,
      (dir / "left.png").string() + " " + (dir / "right.png").string() + " -o " + out +
          " --labels 128 --schedule flat --near-radius 0 --shift-moves=off",
      2.5, SIGINT);
  INFO(r.output);
  CHECK(r.exit_code == 130);
  CHECK_THAT(r.output, Catch::Contains("interrupted by SIGINT"));
  std::ifstream summary(out + "/summary.txt");
  const std::string text((std::istreambuf_iterator<char>(summary)), {});
  CHECK_THAT(text, Catch::Contains("interrupted by SIGINT after") &&
                       Catch::Contains("the labeling written is the best found so far"));
  CHECK_THAT(text, Catch::Contains("(observer)"));
  CHECK(cv::imread(out + "/disparity.png", cv::IMREAD_UNCHANGED).size() == cv::Size(480, 360));
  std::ifstream trace(out + "/trace.csv");
  std::string line, last;
  while (std::getline(trace, line)) last = line;
  CHECK(std::count(last.begin(), last.end(), ',') == 4);  // the last row is complete
}

TEST_CASE("c2f-stereo replaces an earlier run's outputs only when it succeeds", "[stereo][cli]") {
  namespace fs = std::filesystem;
  const auto dir = fs::temp_directory_path() / "c2f-test-cli-rerun";
  fs::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 5);
  const std::string inputs = (dir / "left.png").string() + " " + (dir / "right.png").string();
  const fs::path out = dir / "out";
  auto read_all = [&] {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(out)) {
      std::ifstream in(entry.path(), std::ios::binary);
      files[entry.path().filename().string()] = {std::istreambuf_iterator<char>(in), {}};
    }
    return files;
  };
  auto r = run(inputs + " -o " + out.string() + " --labels 10 --gt " + (dir / "gt.png").string() +
               " --gt-divisor 4 --save-partitions -q");
  REQUIRE(r.exit_code == 0);
  {
    std::ofstream notes(out / "notes.txt");
    notes << "the user's own file";
  }
  const auto first = read_all();
  REQUIRE(first.count("error.png") == 1);
  REQUIRE(first.count("partition-level0.png") == 1);

  // A run that fails late (every trace row is lost on /dev/full) changes nothing.
  r = run(inputs + " -o " + out.string() + " --labels 12 --trace /dev/full -q");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("the trace '/dev/full'"));
  CHECK(read_all() == first);

  // A successful run leaves exactly its own outputs (and the user's file).
  r = run(inputs + " -o " + out.string() + " --labels 12 -q");
  REQUIRE(r.exit_code == 0);
  const auto second = read_all();
  CHECK(second.count("error.png") == 0);
  CHECK(second.count("partition-level0.png") == 0);
  CHECK(second.at("notes.txt") == "the user's own file");
  for (const char* file :
       {"disparity.pfm", "disparity.png", "disparity-colour.png", "trace.csv", "summary.txt"})
    CHECK(second.count(file) == 1);
  CHECK(second.count(".c2f-owner") == 1);  // the folder's owner: c2f-stereo
  CHECK(second.size() == 7);
}

TEST_CASE("c2f-stereo --schedule aggregated solves on a level of aggregated best labels",
          "[stereo][cli][aggregated]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-aggregated";
  std::filesystem::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 7);
  const auto out = dir / "out";
  const auto r =
      run((dir / "left.png").string() + " " + (dir / "right.png").string() + " -o " + out.string() +
          " --labels 8 --schedule aggregated --near-radius 2 -q" + " --threads 2");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::ifstream summary(out / "summary.txt");
  std::stringstream text;
  text << summary.rdbuf();
  CHECK_THAT(text.str(), Catch::Contains("schedule agg:1/cc flat"));
  // One coarse level with fewer groups than the 48 x 32 pixels, then the original problem.
  const std::string groups_line = "partition agg:1/cc: ";
  const auto at = text.str().find(groups_line);
  REQUIRE(at != std::string::npos);
  const long groups = std::stol(text.str().substr(at + groups_line.size()));
  CHECK(groups > 0);
  CHECK(groups < 48 * 32);
  const std::string line = text.str().substr(at, text.str().find('\n', at) - at);
  CHECK_THAT(line, Catch::EndsWith(" s on 2 threads"));  // the level's threads (--threads)
  CHECK_THAT(text.str(), Catch::Contains("level 1: 1536 variables"));
}

TEST_CASE("c2f-stereo stopped while it exports a large model writes nothing and exits 143",
          "[stereo][cli][interrupt]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-export-interrupt";
  std::filesystem::remove_all(dir);
  // 200x150 pixels and 48 labels: about 2.5 GB of UAI text, several seconds of writing; the
  // signal comes while it is written (or before, and then the write stops at once).
  c2f::test::write_synthetic_pair(dir, 200, 150, 2, 6, 5);
  const auto model = dir / "model.uai";
  const auto r = c2f::test::run_tool_interrupted(
      C2F_STEREO_BINARY,
      (dir / "left.png").string() + " " + (dir / "right.png").string() + " -o " +
          (dir / "out").string() + " --labels 48 --export-uai " + model.string(),
      1.0, SIGTERM);
  INFO(r.output);
  CHECK(r.exit_code == 143);
  CHECK_THAT(r.output, Catch::Contains("c2f-stereo: interrupted by SIGTERM while writing the UAI "
                                       "model; nothing was written"));
  CHECK_FALSE(std::filesystem::exists(model));
  CHECK_FALSE(std::filesystem::exists(dir / "model.uai.c2f-partial"));
  CHECK_FALSE(std::filesystem::exists(dir / "out" / "summary.txt"));
}

TEST_CASE("c2f-stereo reads Middlebury 2014 and KITTI scenes and scores them their way",
          "[stereo][cli][data]") {
  const std::string data = C2F_SHARED_DATA_DIR;
  if (!std::filesystem::exists(data + "/middlebury2014")) {
    WARN("no shared data at " << data << ": Middlebury 2014 and KITTI runs not checked");
    return;
  }
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-datasets";
  std::filesystem::remove_all(dir);
  const auto summary_of = [&](const std::string& name) {
    std::ifstream in(dir / name / "summary.txt");
    return std::string((std::istreambuf_iterator<char>(in)), {});
  };
  // Quarter-size Adirondack shrunk 4 more times: ndisp 73 becomes 19 labels, bad 2.0 at full
  // size becomes 0.125 px.
  auto r = run("--scene middlebury2014/Adirondack --data " + data + " --downscale 4 -o " +
               (dir / "adirondack").string() + " --schedule flat --max-steps 3");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(summary_of("adirondack"),
             Catch::Contains("scene middlebury2014/Adirondack 179x124, 19 labels") &&
                 Catch::Contains("bad 2.0 (full size) (> 0.125 px here): nonocc ") &&
                 Catch::Contains("non-occluded pixels from: official mask"));
  r = run("--scene kitti2015/000000_10 --data " + data + " --downscale 6 --labels 24 -o " +
          (dir / "kitti").string() + " --schedule flat --max-steps 3");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(summary_of("kitti"), Catch::Contains("scene kitti2015/000000_10 207x62, 24 labels") &&
                                      Catch::Contains("D1 (> 0.5 px and > 5% here): all "));
  // A schedule that needs more labels than the scene's range is named after loading it.
  r = run("--scene middlebury2014/Adirondack --data " + data + " --downscale 8 -o " +
          (dir / "few").string() + " --schedule cp:20,1");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("--schedule: ") && Catch::Contains("(--labels 10)"));
}

TEST_CASE("c2f-stereo stays within its memory budget: recycled move graphs get what is left",
          "[stereo][cli][memory]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-cli-memory";
  std::filesystem::remove_all(dir);
  c2f::test::write_synthetic_pair(dir, 320, 240, 4, 20, 13);
  const std::string pair = (dir / "left.png").string() + " " + (dir / "right.png").string();
  const auto solve = [&](const std::string& name, const std::string& memory) {
    const auto r = c2f::test::run_tool_measured(
        C2F_STEREO_BINARY,
        pair + " -o " + (dir / name).string() +
            " --labels 48 --schedule flat --near-radius 0 --shift-moves=off --max-steps 150 -q" +
            memory);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    std::ifstream in(dir / name / "summary.txt");
    std::string line;
    while (std::getline(in, line) && line.rfind("memory budget ", 0) != 0) {
    }
    return std::pair{r.peak_kib, line};
  };
  // Every label's graphs fit in 4 GiB; in 0.25 GiB the energy and the run's floor leave room
  // for some of them only.
  const auto [unbounded_kib, unbounded_line] = solve("generous", " --memory 4");
  const auto [bounded_kib, bounded_line] = solve("bounded", " --memory 0.25");
  INFO(unbounded_line << "\n" << bounded_line);
  CHECK_THAT(bounded_line, Catch::StartsWith("memory budget 256.0 MiB (--memory 0.25), recycled "
                                             "move graphs up to "));
#if defined(__SANITIZE_ADDRESS__)
  // Resident sizes there include the sanitizer's shadow memory and quarantine.
  WARN("AddressSanitizer build: peak resident sizes " << bounded_kib << " and " << unbounded_kib
                                                      << " KiB not compared with the budget");
#else
  CHECK(bounded_kib <= 256 * 1024);
  CHECK(unbounded_kib > 256 * 1024);
#endif
  const cv::Mat unbounded =
      cv::imread((dir / "generous/disparity.png").string(), cv::IMREAD_UNCHANGED);
  const cv::Mat bounded =
      cv::imread((dir / "bounded/disparity.png").string(), cv::IMREAD_UNCHANGED);
  REQUIRE_FALSE(bounded.empty());
  CHECK(cv::countNonZero(unbounded != bounded) == 0);
}
