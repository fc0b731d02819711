// c2f-solve: any pairwise UAI model, flat or coarse to fine. The labeling it writes has the
// energy it reports, is no better than the exact optimum (brute force on tiny models; Debian's
// toulbar2 on small random and stereo models, when it is installed), and bad input is an error
// naming it. toulbar2 must also read every model c2f writes.

#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <sstream>
#include <string>

#include "c2f/core/uai.hpp"
#include "support/output_folders.hpp"
#include "support/random_models.hpp"
#include "support/run_tool.hpp"
#include "support/synthetic_segmentation.hpp"
#include "support/synthetic_stereo.hpp"

namespace fs = std::filesystem;
using c2f::Labeling;
using c2f::PairwiseEnergy;

namespace {

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_model(const PairwiseEnergy& energy, const fs::path& path) {
  std::ofstream out(path);
  c2f::write_uai(energy, out);
}

PairwiseEnergy read_model(const fs::path& path) {
  return c2f::read_uai_file(path.string());
}

/// Runs c2f-solve on `model` into `out`; returns the written labeling after checking that the
/// run succeeded and that the summary's final energy is the labeling's energy.
Labeling solve(const fs::path& model, const fs::path& out, const std::string& flags) {
  const auto r = c2f::test::run_tool(C2F_SOLVE_BINARY,
                                     model.string() + " -o " + out.string() + " -q " + flags);
  INFO(flags << "\n" << r.output);
  REQUIRE(r.exit_code == 0);
  const PairwiseEnergy energy = read_model(model);
  std::ifstream mpe(out / "labeling.mpe");
  Labeling labeling =
      c2f::read_uai_mpe(mpe, "labeling.mpe", energy.num_variables(), energy.num_labels());
  std::smatch reported;
  const std::string summary = read_text(out / "summary.txt");
  REQUIRE(std::regex_search(summary, reported, std::regex("final energy ([-0-9.e+]+)")));
  CHECK(std::stod(reported[1]) == Approx(energy.evaluate(labeling)).epsilon(1e-9).margin(1e-6));
  return labeling;
}

/// A fresh, empty folder `name` under the system's temporary folder.
fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("c2f-solve is never better than brute force and reports its labeling's energy",
          "[solve][cli]") {
  const fs::path dir = fresh_folder("c2f-test-solve-brute");
  c2f::test::Rng rng(17);
  for (int trial = 0; trial < 6; ++trial) {
    const int labels = 3 + trial % 2;
    const PairwiseEnergy original = c2f::test::random_energy(rng, 7, labels, 12);
    const fs::path model = dir / ("model" + std::to_string(trial) + ".uai");
    write_model(original, model);
    const PairwiseEnergy energy = read_model(model);
    const double optimum = c2f::test::brute_force_minimum(energy).energy;
    for (const char* flags : {"--schedule flat", "--schedule paper",
                              "--solver icm --schedule auto:0.3,0.6", "--solver lbp"}) {
      const Labeling labeling = solve(model, dir / "out", flags);
      INFO("trial " << trial << " " << flags);
      CHECK(energy.evaluate(labeling) >= optimum - 1e-9);
    }
  }
}

TEST_CASE("c2f-solve refuses bad models and options by name", "[solve][cli][malformed]") {
  const fs::path dir = fresh_folder("c2f-test-solve-bad");
  c2f::test::Rng rng(5);
  write_model(c2f::test::random_grid_energy(rng, 4, 3, 2), dir / "binary.uai");
  write_model(c2f::test::random_grid_energy(rng, 4, 3, 4), dir / "grid.uai");
  std::ofstream(dir / "zero.uai") << "MARKOV\n1\n2\n1\n1 0\n2\n0 1\n";
  std::ofstream(dir / "text.uai") << "hello\n";
  {  // 4 GiB of unary costs declared in a few kilobytes: refused before they are allocated
    std::ofstream huge(dir / "huge.uai");
    huge << "MARKOV\n512\n";
    for (int v = 0; v < 512; ++v) huge << "1048576 ";
    huge << "\n0\n";
  }
  REQUIRE(::mkfifo((dir / "fifo.uai").c_str(), 0600) == 0);
  const std::string out = " -o " + (dir / "out").string();
  const std::string grid = (dir / "grid.uai").string();
  for (const auto& [arguments, expected] : std::vector<std::pair<std::string, std::string>>{
           {(dir / "missing.uai").string() + out, "MODEL: file '"},
           {grid, "-o/--out: an output directory is required"},
           {out, "give MODEL.uai"},
           {grid + " " + grid + out, "unexpected argument"},
           {(dir / "text.uai").string() + out, "text.uai: token 1: network type 'hello'"},
           {(dir / "zero.uai").string() + out, "zero.uai: token 8: factor 0: potential 0"},
           {(dir / "text.uai").string() + out + " --solver swap", "network type 'hello'"},
           {grid + out + " --solver swap", "is not a semi-metric"},
           {grid + out + " --schedule local:1,1", "--schedule: level local:1,1 needs a pixel grid"},
           {grid + out + " --schedule blocks:2/cc", "level blocks:2/cc needs a pixel grid"},
           {grid + out + " --schedule local:1,1 --grid 3x3",
            "--grid: 3x3 is 9 pixels, the model has 12 variables"},
           {grid + out + " --grid 4by3", "--grid: expected WIDTHxHEIGHT"},
           {(dir / "binary.uai").string() + out + " --schedule paper",
            "--schedule: level cp:3,1 has N_L 3 above the 2 labels"},
           {grid + out + " --schedule slic:4", "needs a pixel grid"},
           {grid + out + " --solver magic", "--solver: unknown solver 'magic'"},
           {grid + out + " --flow-parts 4 --solver swap", "--flow-parts with --solver swap"},
           {grid + out + " --flow-parts 4 --maxflow boost",
            "--flow-parts: only our max-flow (--maxflow dynamic) solves in parts"},
           {grid + out + " --flow-parts 256", "--flow-parts"},
           {grid + out + " --bp-schedule bands",
            "--bp-schedule with --solver expansion: it schedules loopy BP's messages"},
           {grid + out + " --solver lbp --bp-schedule async",
            "--bp-schedule: unknown BP schedule 'async'"},
           // c2f-solve's defaults make whole moves (shift moves only where an expansion move is
           // not submodular: --shift-moves auto), so these flags are asked for, not defaults;
           // --near-radius 0 says so again.
           {grid + out + " --solver icm --shift-moves",
            "--shift-moves or --label-order with --solver icm: shift moves are made by expansion"},
           {grid + out + " --near-radius 0 --shift-moves=off --near-levels all",
            "--near-levels: has no effect without --near-radius or --shift-moves"},
           {grid + out + " --near-radius 0 --regions 16",
            "--regions: has no effect without --near-radius"},
           {grid + out + " --near-radius 0 --near-seeds label_and_cheapest",
            "--near-seeds: has no effect without --near-radius"},
           {grid + out + " --near-radius 0 --near-graphs any",
            "--near-graphs: has no effect without --near-radius"},
           {grid + out + " --near-radius 0 --near-min-variables 10",
            "--near-min-variables: has no effect without --near-radius"},
           {grid + out + " --near-radius 2 --near-graphs grids",
            "--near-graphs: unknown energies for near moves 'grids' (expected local or any)"},
           {grid + out + " --near-radius 2 --near-seeds cheapest", "--near-seeds: "},
           {grid + out + " --solver swap --regions 4",
            "--regions with --solver swap: region moves are expansion moves"},
           {grid + out + " --time-limit nan", "--time-limit: expected a finite number"},
           {(dir / "huge.uai").string() + out + " --memory 0.5",
            "huge.uai (512 variables x 1048576 labels, 0 factors) needs 4.0 GiB, more than the "
            "run's memory budget of 512.0 MiB (--memory 0.5)"},
           {(dir / "fifo.uai").string() + out, "fifo.uai' is not a regular file (a FIFO)"},
           {grid + out + " --memory 0.01",
            "grid.uai' solved by expansion needs 128.0 MiB, more than the run's memory budget of "
            "10.2 MiB (--memory 0.01)"},
           // An output over the model, or over one of the run's own outputs (was exit 0).
           {grid + out + " --trace " + grid, "--trace '" + grid + "' is the same file as MODEL"},
           {grid + out + " --trace " + (dir / "out" / "labeling.mpe").string(),
            "is labeling.mpe, a file the run writes into"},
       }) {
    const auto r = c2f::test::run_tool(C2F_SOLVE_BINARY, arguments);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("c2f-solve: error: ") && Catch::Contains(expected));
  }
  CHECK_FALSE(fs::exists(dir / "out"));
  // Grid levels work once the grid is given.
  const Labeling labeling = solve(grid, dir / "out", "--schedule \"local:1,1/cc flat\" --grid 4x3");
  CHECK(labeling.size() == 12);
}

TEST_CASE("c2f-segment and c2f-stereo export models c2f-solve reads", "[solve][cli]") {
  const fs::path dir = fs::temp_directory_path() / "c2f-test-solve-export";
  fs::remove_all(dir);
  const auto files = c2f::test::write_synthetic_segmentation(dir, 24, 18, 2);
  const auto r = c2f::test::run_tool(
      C2F_SEGMENT_BINARY,
      files.image + " " + files.seeds + " --method potts --schedule flat -q -o " +
          (dir / "segment").string() + " --export-uai " + (dir / "segment" / "potts.uai").string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const PairwiseEnergy potts = read_model(dir / "segment" / "potts.uai");
  CHECK(potts.num_variables() == 24 * 18);
  CHECK(potts.num_labels() == 3);
  CHECK(solve(dir / "segment" / "potts.uai", dir / "solved", "--schedule paper").size() == 24 * 18);
  // A run that fails leaves no exported model behind (it is staged like every output).
  const auto failed = c2f::test::run_tool(
      C2F_SEGMENT_BINARY, files.image + " " + files.seeds + " --schedule cp:9,1 -q -o " +
                              (dir / "failed").string() + " --export-uai " +
                              (dir / "failed" / "potts.uai").string());
  CHECK(failed.exit_code == 2);
  CHECK_FALSE(fs::exists(dir / "failed" / "potts.uai"));
}

#ifdef C2F_TOULBAR2
namespace {

/// toulbar2's optimum of `model` (it must read the file and write a complete solution).
Labeling toulbar2_optimum(const fs::path& model, std::size_t num_variables) {
  const fs::path solution = model.string() + ".tb2.sol";
  const auto r = c2f::test::run_tool(C2F_TOULBAR2, model.string() + " -w=" + solution.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("Optimum:"));
  std::ifstream in(solution);
  Labeling labeling;
  for (int label; in >> label;) labeling.push_back(label);
  REQUIRE(labeling.size() == num_variables);
  return labeling;
}

}  // namespace

TEST_CASE("c2f-solve is never better than toulbar2's exact optimum, and toulbar2 reads our files",
          "[solve][cli][toulbar2]") {
  const fs::path dir = fresh_folder("c2f-test-solve-toulbar2");
  // toulbar2 rounds costs to 7 digits (-precision 7): its optimum is exact up to that rounding.
  const auto tolerance = [](double value) { return 1e-5 * std::max(1.0, std::abs(value)); };
  c2f::test::Rng rng(23);
  for (int trial = 0; trial < 4; ++trial) {
    const fs::path model = dir / ("random" + std::to_string(trial) + ".uai");
    write_model(c2f::test::random_grid_energy(rng, 5, 4, 3 + trial % 2), model);
    const PairwiseEnergy energy = read_model(model);
    const double exact = energy.evaluate(toulbar2_optimum(model, energy.num_variables()));
    for (const char* flags : {"--schedule flat", "--schedule paper"}) {
      const double ours = energy.evaluate(solve(model, dir / "out", flags));
      INFO(model << " " << flags << ": ours " << ours << ", toulbar2 " << exact);
      CHECK(ours >= exact - tolerance(exact));
    }
  }
  // A small stereo model exported by c2f-stereo.
  c2f::test::write_synthetic_pair(dir, 24, 16, 1, 4, 7);
  const fs::path stereo_model = dir / "stereo" / "model.uai";
  const auto exported = c2f::test::run_tool(
      C2F_STEREO_BINARY, (dir / "left.png").string() + " " + (dir / "right.png").string() +
                             " --labels 6 --schedule flat -q -o " + (dir / "stereo").string() +
                             " --export-uai " + stereo_model.string());
  INFO(exported.output);
  REQUIRE(exported.exit_code == 0);
  const PairwiseEnergy stereo = read_model(stereo_model);
  CHECK(stereo.num_variables() == 24 * 16);
  const double exact = stereo.evaluate(toulbar2_optimum(stereo_model, stereo.num_variables()));
  for (const char* flags : {"--schedule flat", "--schedule paper",
                            "--grid 24x16 --schedule "
                            "\"local:1,1/cc flat\""}) {
    const double ours = stereo.evaluate(solve(stereo_model, dir / "out", flags));
    INFO(flags << ": ours " << ours << ", toulbar2 " << exact);
    CHECK(ours >= exact - tolerance(exact));
    CHECK(ours <= exact * 1.05 + 1.0);  // expansion on TSGO stays close to the optimum
  }
}
#endif

TEST_CASE("a trace into a pipe nobody reads is an error that leaves no folder",
          "[solve][cli][malformed]") {
  // `--trace /dev/stdout | true`, the run started once `true` has ended: the reader is gone
  // before the trace is written. The write fails (EPIPE), the run ends with exit 1 and a
  // message, and the new output folder goes again (SIGPIPE ended the process without a word,
  // leaving a folder with only a marker).
  const fs::path dir = fresh_folder("c2f-test-solve-pipe");
  c2f::test::Rng rng(9);
  write_model(c2f::test::random_grid_energy(rng, 6, 5, 3), dir / "grid.uai");
  const auto r = c2f::test::run_tool(
      "/bin/bash", "-c '{ sleep 1; " + std::string(C2F_SOLVE_BINARY) + " " +
                       (dir / "grid.uai").string() + " -o " + (dir / "out").string() +
                       " --trace /dev/stdout; } | true; exit ${PIPESTATUS[0]}'");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("c2f-solve: error: ") && Catch::Contains("failed"));
  CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("a folder the run cannot write or clean is refused before the run, leaving nothing",
          "[solve][cli][malformed]") {
  // Permissions bind root nowhere: as root the runs are made as nobody (setpriv), whose folder
  // this is. A folder of mode 555 left one more staging folder behind at every run (exit 0); a
  // subfolder of mode 000 failed the run and left one too.
  const fs::path dir = fresh_folder("c2f-test-solve-permissions");
  c2f::test::Rng rng(4);
  write_model(c2f::test::random_grid_energy(rng, 4, 3, 2), dir / "grid.uai");
  const bool root = ::geteuid() == 0;
  const std::string as_user =
      root ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : std::string();
  const auto solve_as_user = [&] {
    return c2f::test::run_tool(as_user + C2F_SOLVE_BINARY, (dir / "grid.uai").string() + " -o " +
                                                               (dir / "out").string() + " -q");
  };
  if (root) REQUIRE(::chown(dir.c_str(), 65534, 65534) == 0);
  REQUIRE(solve_as_user().exit_code == 0);
  fs::permissions(dir / "out", fs::perms(0555));
  auto r = solve_as_user();
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("cannot be written (Permission denied)"));
  CHECK(c2f::test::run_leftovers(dir / "out") == 0);
  fs::permissions(dir / "out", fs::perms(0755));
  fs::create_directories(dir / "out" / "locked");
  if (root) REQUIRE(::chown((dir / "out" / "locked").c_str(), 65534, 65534) == 0);
  fs::permissions(dir / "out" / "locked", fs::perms::none);
  r = solve_as_user();
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("locked', a folder this run cannot read"));
  CHECK(c2f::test::run_leftovers(dir / "out") == 0);
  fs::permissions(dir / "out" / "locked", fs::perms(0755));
}
