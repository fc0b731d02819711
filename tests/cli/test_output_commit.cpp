// A run's output folder changes in one step (the earlier run's or the new one, never a mix,
// whatever kills the run and whenever), only folders a tool owns are written, and one run at a
// time writes a folder. The kills are injected with strace between the commit's system calls.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "support/output_folders.hpp"
#include "support/run_tool.hpp"
#include "support/synthetic_stereo.hpp"

namespace fs = std::filesystem;

namespace {

using Files = std::map<std::string, std::string>;

/// Every entry of `folder` with its bytes ("/" for a folder), but the marker, which names the
/// process of the run holding the folder (and of a killed one).
Files read_folder(const fs::path& folder) {
  Files files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name == ".c2f-owner") continue;
    if (entry.is_directory()) {
      files[name] = "/";
      continue;
    }
    std::ifstream in(entry.path(), std::ios::binary);
    files[name] = {std::istreambuf_iterator<char>(in), {}};
  }
  return files;
}

c2f::test::ToolResult run_shell(const std::string& command) {
  return c2f::test::run_tool("sh", "-c '" + command + "'");
}

/// strace, with LeakSanitizer off in sanitizer builds (it cannot run under a tracer).
const std::string kStrace =
    "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 /usr/bin/strace";

/// c2f-stereo with `arguments`, run under strace with `injections` (strace -e inject=...).
c2f::test::ToolResult run_stereo_injected(const std::string& injections,
                                          const std::string& arguments) {
  return run_shell(kStrace + " -f -qq -o /dev/null " + injections + " " + C2F_STEREO_BINARY + " " +
                   arguments);
}

struct Scene {
  fs::path dir;
  fs::path out;
  std::string inputs;
};

Scene make_scene(const std::string& name) {
  Scene scene{fs::temp_directory_path() / name, {}, {}};
  fs::remove_all(scene.dir);
  c2f::test::write_synthetic_pair(scene.dir, 48, 32, 2, 6, 5);
  scene.out = scene.dir / "out";
  scene.inputs = (scene.dir / "left.png").string() + " " + (scene.dir / "right.png").string() +
                 " -o " + scene.out.string() + " -q";
  return scene;
}

}  // namespace

TEST_CASE("c2f-stereo refuses a folder it does not own and leaves its files alone",
          "[cli][commit]") {
  const Scene scene = make_scene("c2f-test-commit-users-folder");
  fs::create_directories(scene.out);
  for (const char* name : {"error.png", "partition-level-notes.png"}) {
    std::ofstream(scene.out / name) << "the user's own " << name;
  }
  const Files before = read_folder(scene.out);
  const auto r = c2f::test::run_tool(C2F_STEREO_BINARY, scene.inputs + " --labels 8");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("the output folder '" + scene.out.string() +
                                       "' is not empty and was not written by a c2f tool"));
  CHECK(read_folder(scene.out) == before);
  CHECK_FALSE(fs::exists(scene.out / ".c2f-owner"));
  CHECK(c2f::test::run_leftovers(scene.out) == 0);
}

TEST_CASE("two c2f-stereo runs into one folder at once: the second is refused by name",
          "[cli][commit][strace]") {
  REQUIRE(fs::exists("/usr/bin/strace"));  // scripts/install-deps installs strace
  const Scene scene = make_scene("c2f-test-commit-concurrent");
  // The first run is held for three seconds as it commits (strace delays its exchange); the
  // second starts one second after it.
  const auto r = run_shell(
      kStrace + " -f -qq -o /dev/null -e inject=renameat2:delay_enter=3000000 " +
      C2F_STEREO_BINARY + " " + scene.inputs + " --labels 10 & sleep 1; " + C2F_STEREO_BINARY +
      " " + scene.inputs + " --labels 12; echo second=$?; wait $!; echo first=$?");
  INFO(r.output);
  CHECK_THAT(r.output, Catch::Contains("is being written by another run (c2f-stereo, process "));
  CHECK_THAT(r.output, Catch::Contains("second=1") && Catch::Contains("first=0"));
  std::ifstream summary(scene.out / "summary.txt");
  const std::string text((std::istreambuf_iterator<char>(summary)), {});
  REQUIRE_FALSE(text.empty());
  CHECK_THAT(text, Catch::Contains("10 labels"));  // the first run's, whole
  std::ifstream marker(scene.out / ".c2f-owner");
  CHECK(
      std::string((std::istreambuf_iterator<char>(marker)), {}).rfind("c2f-stereo\nrecord\n", 0) ==
      0);
}

TEST_CASE("a run killed at any step of its commit leaves one run's folder, never a mix",
          "[cli][commit][strace]") {
  REQUIRE(fs::exists("/usr/bin/strace"));  // scripts/install-deps installs strace
  const Scene scene = make_scene("c2f-test-commit-killed");
  REQUIRE(c2f::test::run_tool(C2F_STEREO_BINARY, scene.inputs + " --labels 8 --save-partitions")
              .exit_code == 0);
  const Files first = read_folder(scene.out);
  REQUIRE(first.count("partition-level0.png") == 1);

  SECTION("killed as it exchanges the folders: the earlier run's folder, byte for byte") {
    const auto r =
        run_stereo_injected("-e inject=renameat2:signal=KILL", scene.inputs + " --labels 12");
    CHECK(r.exit_code != 0);
    CHECK(read_folder(scene.out) == first);
    CHECK(c2f::test::run_leftovers(scene.out) == 1);  // its staging folder, removed by the next run
  }
  SECTION("killed just after the exchange: the new run's folder, whole") {
    const auto r =
        run_stereo_injected("-e inject=unlinkat:signal=KILL", scene.inputs + " --labels 12");
    CHECK(r.exit_code != 0);
    const Files now = read_folder(scene.out);
    CHECK(now.count("partition-level0.png") == 0);
    std::ifstream summary(scene.out / "summary.txt");
    CHECK_THAT(std::string((std::istreambuf_iterator<char>(summary)), {}),
               Catch::Contains("12 labels"));
    std::string names;
    for (const auto& [name, bytes] : now) names += name + " ";
    CHECK(names == "disparity-colour.png disparity.pfm disparity.png summary.txt trace.csv ");
  }
  SECTION("a file system that cannot exchange: two renames, and a kill between them is undone") {
    auto r =
        run_stereo_injected("-e inject=renameat2:error=EINVAL -e inject=rename:signal=KILL:when=2",
                            scene.inputs + " --labels 12");
    CHECK(r.exit_code != 0);
    CHECK_FALSE(fs::exists(scene.out));  // the old folder is aside, the new one not yet in place
    // The next run puts the old folder back first; failing late, it changes nothing.
    r = c2f::test::run_tool(C2F_STEREO_BINARY, scene.inputs + " --labels 12 --trace /dev/full");
    CHECK(r.exit_code == 1);
    REQUIRE(fs::exists(scene.out));
    CHECK(read_folder(scene.out) == first);
    // Without a kill, the fallback commits.
    r = run_stereo_injected("-e inject=renameat2:error=EINVAL", scene.inputs + " --labels 12");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(read_folder(scene.out).count("partition-level0.png") == 0);
  }
  // Whatever happened, the next run finds the folder its own, and cleans up.
  const auto r = c2f::test::run_tool(C2F_STEREO_BINARY, scene.inputs + " --labels 9");
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(c2f::test::run_leftovers(scene.out) == 0);
}

TEST_CASE("a FIFO given as --trace is written in place while a process reads it", "[cli][commit]") {
  const Scene scene = make_scene("c2f-test-commit-fifo");
  const fs::path fifo = scene.dir / "trace.fifo";
  const auto r =
      run_shell("mkfifo " + fifo.string() + " && (cat " + fifo.string() + " > " +
                (scene.dir / "read.csv").string() + " &) && sleep 0.5 && " + C2F_STEREO_BINARY +
                " " + scene.inputs + " --labels 8 --trace " + fifo.string());
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(fs::is_fifo(fifo));  // not replaced by a file
  std::ifstream read(scene.dir / "read.csv");
  std::string header;
  std::getline(read, header);
  CHECK(header == "time_s,level,step,energy,num_vars");
  CHECK_FALSE(fs::exists(scene.out / "trace.csv"));
}

TEST_CASE("a user's folder standing where an output goes is refused, never replaced",
          "[cli][commit]") {
  const Scene scene = make_scene("c2f-test-commit-folder-in-the-way");
  REQUIRE(c2f::test::run_tool(C2F_STEREO_BINARY, scene.inputs + " --labels 8").exit_code == 0);
  for (const char* name : {"summary.txt", "trace.csv"}) {
    fs::remove(scene.out / name);
    fs::create_directories(scene.out / name / "inside");
  }
  const Files before = read_folder(scene.out);
  const auto r = c2f::test::run_tool(C2F_STEREO_BINARY, scene.inputs + " --labels 8");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("', which this run writes and which no earlier run of "
                                       "c2f-stereo wrote"));
  CHECK(read_folder(scene.out) == before);
  CHECK(fs::is_directory(scene.out / "trace.csv" / "inside"));
  CHECK(c2f::test::run_leftovers(scene.out) == 0);
}

TEST_CASE("files a user's process creates while runs commit are never lost", "[cli][commit]") {
  // A writer creates 600 files in the folder while 25 runs commit one after the other, and
  // lists each file it created. A file made in the old version between a commit's carry-over
  // and its exchange, or while the old version was removed, was once removed with it. A create
  // that resolved the folder's name to the old version and then found it removed fails (the
  // writer sees the error), so the check is against the files the writer did create.
  const Scene scene = make_scene("c2f-test-commit-race");
  REQUIRE(c2f::test::run_tool(C2F_STEREO_BINARY, scene.inputs + " --labels 4").exit_code == 0);
  const std::string out = scene.out.string();
  const fs::path created_list = scene.out.parent_path() / "created.txt";
  const auto r = run_shell("(for i in $(seq 1 600); do echo $i > " + out + "/user-$i.txt && echo " +
                           out + "/user-$i.txt >> " + created_list.string() +
                           "; done) & writer=$!; for run in $(seq 1 25); do " + C2F_STEREO_BINARY +
                           " " + scene.inputs + " --labels 4 || exit 3; done; wait $writer");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::ifstream list(created_list);
  int created = 0, lost = 0;
  for (std::string path; std::getline(list, path); ++created) lost += !fs::exists(path);
  CHECK(created > 0);
  CHECK(lost == 0);
  int found = 0;
  for (const auto& entry : fs::directory_iterator(scene.out))
    found += entry.path().filename().string().rfind("user-", 0) == 0;
  CHECK(found == created);
  CHECK(c2f::test::run_leftovers(scene.out) == 0);
}
