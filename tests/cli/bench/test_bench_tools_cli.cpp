// The benchmark tools (built with the benchmarks): malformed arguments are an error naming the
// option and what was expected (exit code 2, before any data is read).

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "support/run_tool.hpp"

namespace {

/// The line of `text` that starts with `start` (without its newline); empty when there is none.
std::string line_starting(const std::string& text, const std::string& start) {
  const auto at = text.find(start);
  return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
}

/// The cells of a markdown table row "| a | b |": "", " a ", " b " and "" (the text before
/// the first bar is dropped, the text after the last one kept).
std::vector<std::string> markdown_cells(const std::string& line) {
  std::vector<std::string> cells;
  for (std::size_t bar = 0; (bar = line.find('|', bar)) != std::string::npos; ++bar)
    cells.push_back(line.substr(bar + 1, line.find('|', bar + 1) - bar - 1));
  return cells;
}

/// True when the shared data holds `needed`; otherwise warns that the test is skipped for want
/// of the shared `what` data (the project does not need that data to build or test).
bool shared_data_has(const std::filesystem::path& needed, const char* what) {
  if (std::filesystem::exists(needed)) return true;
  WARN("no shared " << what << " data at " << std::filesystem::path(C2F_SHARED_DATA_DIR)
                    << ": skipped");
  return false;
}

}  // namespace

TEST_CASE("the benchmark tools refuse malformed arguments by name", "[bench][cli][malformed]") {
  const std::string bench = C2F_BENCH_DIR;
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {"c2f-bench-expansion", "run Teddy --labels abc",
       "--labels: expected an integer in [2, 256], got 'abc'"},
      {"c2f-bench-expansion", "", "expected 'run SCENE' or 'summarize ROWS.tsv'"},
      {"c2f-bench-expansion", "walk Teddy", "expected 'run SCENE' or 'summarize ROWS.tsv'"},
      {"c2f-bench-expansion", "run Teddy --graph-memory nan", "--graph-memory: expected a finite"},
      {"c2f-bench-stereo", "run Teddy --time-limit nan",
       "--time-limit: expected a finite number in (0, 1e+07], got 'nan'"},
      {"c2f-bench-stereo", "run Teddy --schedule cp:1", "--schedule: level 'cp:1'"},
      {"c2f-bench-stereo", "run Teddy --maxflow quick", "--maxflow: unknown max-flow backend"},
      {"c2f-bench-stereo", "run Teddy --coarse-tolerance 2",
       "--coarse-tolerance: expected a finite number in [0, 1), got '2'"},
      {"c2f-bench-stereo", "run Teddy --c2f-near-radius -2",
       "--c2f-near-radius: expected an integer in [0, "},
      {"c2f-bench-stereo", "run Teddy --near-levels some",
       "--near-levels: unknown near-move levels 'some' (expected original or all)"},
      {"c2f-bench-stereo", "run Teddy --flat-near-radius 5 --near-levels all",
       "--near-levels: has no effect without --c2f-near-radius or --c2f-shift-moves"},
      {"c2f-bench-stereo", "run Teddy Dolls", "unexpected argument 'Dolls'"},
      {"c2f-bench-stereo", "run Teddy --memory -1",
       "--memory: expected a finite number in [0, 1e+06], got '-1'"},
      {"c2f-bench-segment", "run set name --time-limit 0",
       "--time-limit: expected a finite number in (0, 1e+07], got '0'"},
      {"c2f-bench-segment", "run set name --configs nope",
       "--configs: unknown configuration 'nope'"},
      {"c2f-bench-segment", "run set name --configs ''",
       "--configs: expected a comma-separated list of configurations or all, got ''"},
      {"c2f-bench-segment", "run set name --alpha 1",
       "--alpha: expected a finite number in [0, 1), got '1'"},
      {"c2f-bench-segment", "run set name --memory -1",
       "--memory: expected a finite number in [0, 1e+06], got '-1'"},
      {"c2f-bench-segment", "run set name --near-radius 0",
       "--near-radius: expected an integer in [1, 1000], got '0'"},
      {"c2f-bench-levels", "", "give SCENE"},
      {"c2f-bench-levels", "Teddy --schedule cp:x", "--schedule: level 'cp:x'"},
      {"c2f-bench-partitions", "data more", "unexpected argument 'more'"},
      {"c2f-bench-published", "--data /nonexistent",
       "--data: no folder '/nonexistent/coopcuts/runMultilabel/seeds'"},
      {"c2f-bench-published", "more", "unexpected argument 'more'"},
      {"c2f-bench-published-fit", "--lambdas 1,,2", "--lambdas: expected a finite number"},
      {"c2f-bench-published-fit", "--thetas 0.001,", "--thetas: expected a comma-separated list"},
      {"c2f-bench-published-fit", "--alphas 1", "--alphas: expected a finite number in [0, 1)"},
      {"c2f-bench-published-fit", "--top -1", "--top: expected an integer in [0, 1000]"},
      {"c2f-bench-crossval", "run --data /nonexistent",
       "--data: no image of '/nonexistent/coopcuts/runMultilabel' has seeds and a ground truth"},
      {"c2f-bench-crossval", "run --plateau later", "--plateau: expected auto or sweep"},
      {"c2f-bench-crossval", "run --method annealing", "--method: unknown auxiliary-variable"},
      {"c2f-bench-crossval", "run --kmeans fast", "--kmeans: expected reference or plusplus"},
      {"c2f-bench-crossval", "summarize /nonexistent.tsv",
       "rows file '/nonexistent.tsv' does not exist"},
      {"c2f-bench-crossval", "walk", "expected 'run' or 'summarize ROWS.tsv...'"},
      // A device is refused by the input layer before it is read.
      {"c2f-bench-stereo", "summarize /dev/null",
       "rows file '/dev/null' is not a regular file (a device)"},
      {"c2f-bench-segment", "summarize /dev/null",
       "rows file '/dev/null' is not a regular file (a device)"},
      {"c2f-bench-expansion", "summarize /dev/null",
       "rows file '/dev/null' is not a regular file (a device)"},
      {"c2f-bench-crossval", "summarize /dev/null",
       "rows file '/dev/null' is not a regular file (a device)"},
  };
  for (const auto& [tool, arguments, expected] : cases) {
    const auto r = c2f::test::run_tool(bench + "/" + tool, arguments);
    INFO(tool << " " << arguments << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains(tool + ": error: ") && Catch::Contains(expected));
  }
}

TEST_CASE("a rows file with a NaN energy or a garbled number is not summarised",
          "[bench][cli][malformed]") {
  const std::string bench = C2F_BENCH_DIR;
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-bench-rows";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto rows = [&](const char* name, const std::string& row) {
    std::ofstream(dir / name)
        << "image\tpixels\tlabels\tconfig\tcoop_energy\terror\tseconds\tsteps\t"
           "reason\treach_seconds\treach_ratio\tdeadline_error_flat\t"
           "deadline_error_c2f\n"
        << row << "\n";
    return (dir / name).string();
  };
  const std::string nan_energy =
      rows("nan.tsv", "fruits\t100\t3\tflat\tnan\t0.1\t2.0\t10\tconverged\tnan\tnan\t0.1\t0.1");
  const std::string garbled =
      rows("garbled.tsv", "fruits\t100\t3\tflat\t12x\t0.1\t2.0\t10\tconverged\t1\t1\t0.1\t0.1");
  for (const auto& [file, expected] :
       {std::pair{nan_energy,
                  "row 'fruits', column coop_energy: expected a finite number, got 'nan'"},
        std::pair{garbled,
                  "row 'fruits', column coop_energy: expected a finite number, got '12x'"}}) {
    const auto r = c2f::test::run_tool(bench + "/c2f-bench-segment", "summarize " + file);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains(expected));
  }
}

TEST_CASE("the benchmark scripts print their usage and refuse a missing data folder untouched",
          "[bench][cli][malformed]") {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "c2f-test-scripts";
  std::filesystem::remove_all(out);
  for (const char* script :
       {"bench/solvers/run-backends", "bench/stereo/run-middlebury", "bench/stereo/run-scaling",
        "bench/stereo/run-threads", "bench/segment/run-coopcuts", "bench/segment/run-kmeans-seeds",
        "bench/segment/run-crossval"}) {
    const std::string path = std::string(C2F_SOURCE_DIR) + "/" + script;
    const auto help = c2f::test::run_tool(path, "--help");
    INFO(script << "\n" << help.output);
    CHECK(help.exit_code == 0);
    CHECK_THAT(help.output, Catch::Contains("Runs") || Catch::Contains("Segments"));
    // Once, "--help" was read as the data folder and the default output's rows were emptied.
    const auto missing = c2f::test::run_tool(path, "/nonexistent-c2f-data " + out.string());
    INFO(missing.output);
    CHECK(missing.exit_code != 0);
    CHECK_THAT(missing.output, Catch::Contains("/nonexistent-c2f-data"));
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

TEST_CASE("run-coopcuts refuses a malformed model flag by name before writing anything",
          "[bench][cli][malformed]") {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "c2f-test-coopcuts";
  std::filesystem::remove_all(out);
  const std::string script = std::string(C2F_SOURCE_DIR) + "/bench/segment/run-coopcuts";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"multilabel --gamma 1", "unknown flag '--gamma'"},
      {"multilabel --lambda", "--lambda needs a value"},
  };
  for (const auto& [arguments, expected] : cases) {
    const auto r = c2f::test::run_tool(
        script, std::string(C2F_SHARED_DATA_DIR) + " " + out.string() + " " + arguments);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("run-coopcuts: ") && Catch::Contains(expected));
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

TEST_CASE("c2f-bench-published recomputes the published pixel errors and descends from them",
          "[bench][cli][segmentation][data]") {
  const std::filesystem::path data = C2F_SHARED_DATA_DIR;
  if (!shared_data_has(data / "coopcuts/runMultilabel/results", "coopCuts")) return;
  const auto r = c2f::test::run_tool(std::string(C2F_BENCH_DIR) + "/c2f-bench-published",
                                     "--data " + data.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // The errors Kohli, Osokin and Jegelka (CVPR 2013) report for these images, to two decimals:
  // what our GT reading and pixel_error must give for their own published labelings.
  const std::vector<std::tuple<std::string, std::string, double>> published = {
      {"1_11_s", "alphaExpResult", 3.00},  {"1_11_s", "coopResult", 2.63},
      {"2_21_s", "alphaExpResult", 5.67},  {"2_21_s", "coopResult", 4.62},
      {"17_12_s", "alphaExpResult", 5.12}, {"17_12_s", "coopResult", 4.53}};
  for (const auto& [image, method, error] : published) {
    const std::string line = line_starting(r.output, "| " + image + " | " + method + " | ");
    REQUIRE_FALSE(line.empty());
    // | image | labeling | energy | Potts energy | error | energy after descent | its error |
    const std::vector<std::string> cells = markdown_cells(line);
    INFO(line);
    REQUIRE(cells.size() == 8);
    CHECK(std::abs(std::stod(cells[4]) - error) <= 0.006);
    // The descent starts from the published labeling and never raises its energy.
    CHECK(std::stod(cells[5]) <= std::stod(cells[2]));
  }
}

TEST_CASE("c2f-bench-published-fit ranks models by the descent c2f-bench-published reports",
          "[bench][cli][segmentation][data]") {
  const std::filesystem::path data = C2F_SHARED_DATA_DIR;
  if (!shared_data_has(data / "coopcuts/runMultilabel/results", "coopCuts")) return;
  const std::string bench = C2F_BENCH_DIR;
  const auto scores =
      c2f::test::run_tool(bench + "/c2f-bench-published",
                          "--data " + data.string() + " --lambda 1.5 --theta 0.001 --alpha 0");
  const auto fit = c2f::test::run_tool(
      bench + "/c2f-bench-published-fit",
      "--data " + data.string() + " --lambdas 1.5 --thetas 0.005,0.001 --alphas 0 --top 0");
  INFO(scores.output << "\n" << fit.output);
  REQUIRE(scores.exit_code == 0);
  REQUIRE(fit.exit_code == 0);
  // The header names the images; each model's row has one gain per image and their mean.
  const auto header = markdown_cells(line_starting(fit.output, "| lambda | theta | alpha |"));
  const auto theta_001 = markdown_cells(line_starting(fit.output, "| 1.5 | 0.001 | 0 |"));
  const auto theta_005 = markdown_cells(line_starting(fit.output, "| 1.5 | 0.005 | 0 |"));
  REQUIRE(header.size() == 8);  // 3 parameters, 3 images, the mean, and the end of the line
  REQUIRE(theta_001.size() == header.size());
  REQUIRE(theta_005.size() == header.size());
  // Ranked by mean gain, smallest first.
  const bool first_is_001 =
      fit.output.find("| 1.5 | 0.001 | 0 |") < fit.output.find("| 1.5 | 0.005 | 0 |");
  CHECK((std::stod(theta_001[6]) <= std::stod(theta_005[6])) == first_is_001);
  // Each gain is (E(published) - E(descended)) / E(published) as c2f-bench-published shows it.
  double mean = 0.0;
  for (std::size_t image = 3; image < 6; ++image) {
    const std::string name = header[image].substr(header[image].find("gain ") + 5);
    const auto row = markdown_cells(
        line_starting(scores.output, "| " + name.substr(0, name.size() - 1) + " | coopResult |"));
    REQUIRE(row.size() == 8);
    const double before = std::stod(row[2]), after = std::stod(row[5]);
    CHECK(std::abs(std::stod(theta_001[image]) - 100 * (before - after) / before) <= 0.001);
    mean += std::stod(theta_001[image]) / 3;
  }
  CHECK(std::abs(std::stod(theta_001[6]) - mean) <= 0.002);
  CHECK_THAT(fit.output, !Catch::Contains("Our greedy"));
}

TEST_CASE("c2f-bench-stereo and c2f-bench-levels take superpixel schedules, as c2f-stereo does",
          "[bench][cli][stereo][data]") {
  const std::filesystem::path data = C2F_SHARED_DATA_DIR;
  if (!shared_data_has(data / "scenes.csv", "Middlebury")) return;
  const std::string bench = C2F_BENCH_DIR;
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "c2f-test-bench-slic";
  std::filesystem::remove_all(out);
  // Once, a slic:S level was refused here ("no superpixel source") although c2f-stereo ran it.
  const auto run = c2f::test::run_tool(
      bench + "/c2f-bench-stereo",
      "run Teddy --schedule \"slic:8 flat\" --downscale 3 --labels 28 --header --out " +
          (out / "rows").string() + " --data " + data.string());
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK(std::filesystem::exists(out / "rows" / "Teddy-c2f.csv"));
  // The C2F row ends on the original problem, converged like the flat one.
  CHECK_THAT(run.output,
             Catch::Contains("Teddy\t") && Catch::Contains("converged\tconverged\t28\t"));

  // A Middlebury 2014 scene: its own label count (ndisp 73 shrunk by 4) and measure, and the
  // data preparation's time (median of three on each thread count) and threads in the row;
  // the summary reads such rows.
  const auto scene2014 = c2f::test::run_tool(
      bench + "/c2f-bench-stereo",
      "run middlebury2014/Adirondack --schedule aggregated --downscale 4 --threads 2 "
      "--prep-one-thread --prep-repeats 3 --memory 1 --header --out " +
          (out / "rows2014").string() + " --data " + data.string());
  INFO(scene2014.output);
  REQUIRE(scene2014.exit_code == 0);
  CHECK_THAT(scene2014.output,
             Catch::Contains("labels\tprep_seconds\tthreads\tc2f_band_seconds\tband_ratio\t"
                             "prep_one_thread_seconds\tprep_peak_mib\tflat_peak_mib\tc2f_peak_mib\t"
                             "memory_gib\n") &&
                 Catch::Contains("middlebury2014/Adirondack\t22196\t") &&
                 Catch::Contains("\t19\t") && Catch::Contains("\t1.00\n"));
  // The one-thread preparations were timed (the six energies matched, else the run stops) and
  // each stretch's peak resident size is a number of MiB.
  const std::size_t row_start = scene2014.output.find("\nmiddlebury2014/Adirondack\t") + 1;
  std::stringstream row(
      scene2014.output.substr(row_start, scene2014.output.find('\n', row_start) - row_start));
  std::vector<std::string> fields;
  for (std::string field; std::getline(row, field, '\t');) fields.push_back(field);
  REQUIRE(fields.size() == 30);
  CHECK(std::stod(fields[25]) > 0.0);
  for (const int column : {26, 27, 28}) CHECK(std::stod(fields[column]) > 10.0);
  {
    std::ofstream(out / "rows2014.tsv")
        << scene2014.output.substr(scene2014.output.find("scene\t"));
  }
  const auto table = c2f::test::run_tool(bench + "/c2f-bench-stereo",
                                         "summarize " + (out / "rows2014.tsv").string());
  INFO(table.output);
  CHECK(table.exit_code == 0);
  CHECK_THAT(table.output, Catch::Contains("| middlebury2014/Adirondack |") &&
                               Catch::Contains("| 19 | ") && Catch::Contains(" (2) |") &&
                               Catch::Contains("C2F within 1e-4 of flat E (s)") &&
                               Catch::Contains("peak MiB prep / flat / C2F"));

  // A repeat count outside 1..100 is refused before anything is prepared.
  const auto no_repeats = c2f::test::run_tool(
      bench + "/c2f-bench-stereo",
      "run middlebury2014/Adirondack --downscale 4 --prep-repeats 0 --data " + data.string());
  CHECK(no_repeats.exit_code != 0);
  CHECK_THAT(no_repeats.output, Catch::Contains("--prep-repeats"));

  const auto levels = c2f::test::run_tool(
      bench + "/c2f-bench-levels", "Teddy --schedule \"slic:16 slic:8\" --data " + data.string());
  INFO(levels.output);
  REQUIRE(levels.exit_code == 0);
  CHECK_THAT(levels.output, Catch::Contains("\nslic:16 ") && Catch::Contains("\nslic:8 ") &&
                                Catch::Contains("\noriginal "));
  std::filesystem::remove_all(out);
}

TEST_CASE("c2f-bench-segment compares each coarse-to-fine run with its own flat run",
          "[bench][cli][segmentation][data]") {
  const std::filesystem::path data = C2F_SHARED_DATA_DIR;
  if (!shared_data_has(data / "coopcuts/runMultilabel/seeds/1_11_s.png", "coopCuts")) return;
  const std::string tool = std::string(C2F_BENCH_DIR) + "/c2f-bench-segment";
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "c2f-test-bench-seg";
  std::filesystem::remove_all(out);
  const std::string common = "run multilabel 1_11_s --data " + data.string() + " --out " +
                             out.string() + " --lambda 0.5 --theta 0.0007 --alpha 0.2";
  // A coarse-to-fine configuration without its flat run is refused by name, before any run.
  const auto alone = c2f::test::run_tool(tool, common + " --configs c2f-slic-greedy-zero");
  INFO(alone.output);
  CHECK(alone.exit_code == 2);
  CHECK_THAT(alone.output, Catch::Contains("c2f-slic-greedy-zero is compared with "
                                           "flat-greedy-zero, which is not in the list"));
  CHECK_FALSE(std::filesystem::exists(out / "1_11_s-c2f-slic-greedy-zero.csv"));
  // A budget the data preparation cannot fit is refused before anything is built or written.
  const auto small = c2f::test::run_tool(tool, common + " --configs potts --memory 0.01");
  INFO(small.output);
  CHECK(small.exit_code == 2);
  CHECK_THAT(small.output, Catch::Contains("segmenting multilabel/1_11_s needs ") &&
                               Catch::Contains("more than the run's memory budget of 10.2 MiB "
                                               "(--memory 0.01)"));
  CHECK_FALSE(std::filesystem::exists(out / "1_11_s-potts.csv"));

  const auto run = c2f::test::run_tool(
      tool,
      common + " --configs flat-mm,c2f-slic-mm,flat-mm-near,c2f-slic-mm-near --near-radius 4");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  // The rows, one per configuration, tab-separated (progress on stderr has no tabs).
  std::vector<std::vector<std::string>> rows;
  std::stringstream lines(run.output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("1_11_s\t", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, '\t');) cells.push_back(cell);
    rows.push_back(cells);
  }
  REQUIRE(rows.size() == 4);
  for (const auto& [flat_name, c2f_name, at] :
       {std::tuple{"flat-mm", "c2f-slic-mm", 0},
        std::tuple{"flat-mm-near", "c2f-slic-mm-near", 2}}) {
    const auto& f = rows[at];
    const auto& c = rows[at + 1];
    REQUIRE(f.size() == 13);
    REQUIRE(c.size() == 13);
    CHECK(f[3] == flat_name);
    CHECK(c[3] == c2f_name);
    CHECK(f[8] == "converged");
    CHECK(c[8] == "converged");
    // The ratio is the time C2F first reaches its flat run's final energy over that run's whole
    // time; a run that never reaches it ends no lower than flat (energies printed to 1e-6, times
    // to 1 ms).
    const double flat_energy = std::stod(f[4]), flat_seconds = std::stod(f[6]);
    if (c[9] != "nan") {
      const double reach = std::stod(c[9]);
      CHECK(std::stod(c[4]) <= flat_energy + 1e-6);
      CHECK(reach > 0.0);
      CHECK(reach <= std::stod(c[6]));
      CHECK(std::stod(c[10]) == Approx(reach / flat_seconds).epsilon(0.01));
    } else {
      CHECK(std::stod(c[4]) >= flat_energy - 1e-6);
    }
  }
  CHECK(std::filesystem::exists(out / "1_11_s-c2f-slic-mm.csv"));
  std::filesystem::remove_all(out);
}

TEST_CASE("c2f-bench-crossval chooses every image's model without that image",
          "[bench][cli][segmentation]") {
  // Two models, two tuning and one aside image per set. A model's score on some images is the
  // mean of the two sets' mean errors. On all tuning images (M1, M2, B1, B2): A scores
  // ((.10 + .02) / 2 + (.01 + .01) / 2) / 2 = .035 and B ((.03 + .05) / 2 + .02) / 2 = .03: B,
  // so the aside images M3 and B3 get B's 4% and 1%. Without M1: A (.02 + .01) / 2 = .015 beats
  // B (.05 + .02) / 2 = .035, so M1 gets A's 10%; without M2: B (.025 against .055), 5%;
  // without B1 or B2: B (.03 against .035), 2% each.
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-crossval";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto rows = dir / "rows.tsv";
  {
    std::ofstream file(rows);
    file << "method\tschedule\tkmeans\tlambda\ttheta\talpha\tset\timage\taside\terror\tenergy\n";
    const std::vector<std::tuple<const char*, const char*, int, double, double>> images = {
        {"multilabel", "M1", 0, 0.10, 0.03}, {"multilabel", "M2", 0, 0.02, 0.05},
        {"multilabel", "M3", 1, 0.05, 0.04}, {"binary", "B1", 0, 0.01, 0.02},
        {"binary", "B2", 0, 0.01, 0.02},     {"binary", "B3", 1, 0.03, 0.01}};
    for (const char* model : {"1\t0.001\t0", "2\t0.001\t0"}) {
      for (const auto& [set, name, aside, a, b] : images) {
        file << "mm\tflat\treference\t" << model << "\t" << set << "\t" << name << "\t" << aside
             << "\t" << (model[0] == '1' ? a : b) << "\t100\n";
      }
    }
  }
  const std::string tool = std::string(C2F_BENCH_DIR) + "/c2f-bench-crossval";
  const auto r = c2f::test::run_tool(tool, "summarize " + rows.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("Chosen on all tuning images: 2 / 0.001 / 0"));
  const auto row = [&](const std::string& image) {
    return markdown_cells(line_starting(r.output, "| " + image + " | "));
  };
  CHECK(row("M1")[3] == " 1 / 0.001 / 0 ");
  CHECK(row("M1")[4] == " 10.00% ");
  CHECK(row("M2")[3] == " 2 / 0.001 / 0 ");
  CHECK(row("M2")[4] == " 5.00% ");
  CHECK(row("B1")[4] == " 2.00% ");
  CHECK(row("M3")[2] == " yes ");
  CHECK(row("M3")[4] == " 4.00% ");
  CHECK(row("B3")[4] == " 1.00% ");
  CHECK(markdown_cells(line_starting(r.output, "| mean, tuning (leave one out) multilabel"))[3] ==
        " 7.50% ");
  CHECK(markdown_cells(line_starting(r.output, "| mean, aside binary"))[3] == " 1.00% ");

  // A model without a row for every image is refused by name.
  std::ofstream(rows, std::ios::app) << "mm\tflat\treference\t3\t0.001\t0\tbinary\tB1\t0\t0.5\t1\n";
  const auto partial = c2f::test::run_tool(tool, "summarize " + rows.string());
  CHECK(partial.exit_code == 2);
  CHECK_THAT(partial.output, Catch::Contains("model 3 / 0.001 / 0 lacks some images' rows"));
  std::filesystem::remove_all(dir);
}
