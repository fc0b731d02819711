// OutputFolder: a run's folder changes in one step, only folders a tool owns are written, one run
// at a time; StagedFile: an output elsewhere is replaced in one step, never over a link or FIFO.

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "c2f/support/output_file.hpp"
#include "folder_swap.hpp"
#include "output_folder.hpp"
#include "staged_file.hpp"
#include "staged_paths.hpp"
#include "support/output_folders.hpp"

namespace {

namespace fs = std::filesystem;
using c2f::examples::OutputFolder;

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// Every entry of `folder` (recursively) with its content ("/" for a folder).
std::map<std::string, std::string> contents(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    const std::string name = entry.path().lexically_relative(folder).string();
    files[name] = entry.is_directory() ? "/" : read_text(entry.path());
  }
  return files;
}

/// A fresh, empty test folder.
fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("OutputFolder replaces the folder in one step and keeps the user's files", "[output]") {
  const fs::path dir = fresh("c2f-test-output-folder") / "out";
  {
    OutputFolder first(dir, "c2f-test", {"summary.txt", "trace.csv", "partition-level*.png"});
    write_text(first.staging() / "summary.txt", "old summary");
    write_text(first.staging() / "partition-level0.png", "old picture");
    first.commit();
  }
  write_text(dir / "notes.txt", "the user's own file");
  write_text(dir / "partition-level-notes.png", "owned by name, yet the user's");
  fs::create_directories(dir / "mine");
  write_text(dir / "mine" / "more.txt", "more of the user's");
  struct stat before {};
  REQUIRE(::stat((dir / "notes.txt").c_str(), &before) == 0);
  {
    OutputFolder output(dir, "c2f-test", {"summary.txt", "trace.csv", "partition-level*.png"});
    CHECK(output.owns("partition-level12.png"));
    CHECK_FALSE(output.owns("notes.txt"));
    CHECK(output.staging().parent_path() == dir.parent_path());  // beside, not inside
    write_text(output.stage(dir / "summary.txt"), "new summary");
    write_text(output.stage(dir / "trace.csv"), "new trace");
    CHECK(read_text(dir / "summary.txt") == "old summary");  // nothing changes before commit
    CHECK(output.commit().size() == 2);
  }
  CHECK(read_text(dir / "summary.txt") == "new summary");
  CHECK(read_text(dir / "trace.csv") == "new trace");
  CHECK_FALSE(fs::exists(dir / "partition-level0.png"));  // recorded, not written this time
  CHECK(read_text(dir / "notes.txt") == "the user's own file");
  CHECK(read_text(dir / "partition-level-notes.png") == "owned by name, yet the user's");
  CHECK(read_text(dir / "mine" / "more.txt") == "more of the user's");
  struct stat after {};
  REQUIRE(::stat((dir / "notes.txt").c_str(), &after) == 0);
  CHECK(after.st_ino == before.st_ino);  // the same file, linked into the new folder
  CHECK(read_text(dir / c2f::examples::FolderClaim::kMarker).rfind("c2f-test\nrecord\n", 0) == 0);
  CHECK(c2f::test::run_leftovers(dir) == 0);
}

TEST_CASE("OutputFolder replaces only the files its runs wrote, and keeps what appears meanwhile",
          "[output]") {
  const fs::path dir = fresh("c2f-test-output-folder-record") / "out";
  const std::vector<std::string> owned{"summary.txt", "trace.csv"};
  {
    OutputFolder first(dir, "c2f-test", owned);
    write_text(first.staging() / "summary.txt", "ours");
    first.commit();
  }
  // A user's folder where a fixed output goes: refused before the run, left as it is.
  fs::create_directories(dir / "trace.csv" / "inside");
  CHECK_THROWS_WITH(OutputFolder(dir, "c2f-test", owned),
                    Catch::Contains("holds 'trace.csv', which this run writes and which no earlier "
                                    "run of c2f-test wrote"));
  CHECK(fs::is_directory(dir / "trace.csv" / "inside"));
  fs::remove_all(dir / "trace.csv");
  // A user's file put in place of a file the tool wrote (another inode) is the user's now.
  // Written beside it and renamed over it, so that it cannot reuse the freed inode number.
  write_text(dir / "summary.txt.users", "the user's summary");
  fs::rename(dir / "summary.txt.users", dir / "summary.txt");
  CHECK_THROWS_WITH(OutputFolder(dir, "c2f-test", owned), Catch::Contains("holds 'summary.txt'"));
  CHECK(read_text(dir / "summary.txt") == "the user's summary");
  fs::remove(dir / "summary.txt");
  // A user's folder named like a staging folder of earlier versions is the user's: kept.
  fs::create_directories(dir / ".c2f-staging-1-0");
  write_text(dir / ".c2f-staging-1-0" / "mine.txt", "the user's");
  // A file made in the folder while a run commits is in the new version.
  {
    OutputFolder output(dir, "c2f-test", owned);
    write_text(output.staging() / "summary.txt", "new");
    write_text(dir / "made-meanwhile.txt", "the user's");
    output.commit();
  }
  CHECK(read_text(dir / "made-meanwhile.txt") == "the user's");
  CHECK(read_text(dir / ".c2f-staging-1-0" / "mine.txt") == "the user's");
  CHECK(read_text(dir / "summary.txt") == "new");
}

TEST_CASE("OutputFolder refuses a marker it did not make", "[output]") {
  const fs::path root = fresh("c2f-test-output-folder-marker");
  const fs::path dir = root / "out";
  fs::create_directories(dir);
  write_text(dir / "summary.txt", "the user's summary");
  write_text(dir / c2f::examples::FolderClaim::kMarker, "");
  CHECK_THROWS_WITH(OutputFolder(dir, "c2f-test", {"summary.txt"}),
                    Catch::Contains("has an empty .c2f-owner, which no c2f tool wrote"));
  write_text(dir / c2f::examples::FolderClaim::kMarker, "my notes\n");
  CHECK_THROWS_WITH(OutputFolder(dir, "c2f-test", {"summary.txt"}),
                    Catch::Contains("names no c2f tool"));
  // A marker that is a hard link to a file of the user's would be overwritten: refused.
  fs::remove(dir / c2f::examples::FolderClaim::kMarker);
  write_text(root / "diary.txt", "c2f-test\n");
  fs::create_hard_link(root / "diary.txt", dir / c2f::examples::FolderClaim::kMarker);
  CHECK_THROWS_WITH(OutputFolder(dir, "c2f-test", {"summary.txt"}),
                    Catch::Contains("with 2 hard links, 1 of them outside the runs' folders"));
  CHECK(read_text(root / "diary.txt") == "c2f-test\n");
  CHECK(read_text(dir / "summary.txt") == "the user's summary");
  // A user's folder named like a killed run's staging folder is not one: kept.
  fs::remove(dir / c2f::examples::FolderClaim::kMarker);
  fs::remove(dir / "summary.txt");
  fs::create_directories(root / ".out.c2f-staging-999999999-0");
  write_text(root / ".out.c2f-staging-999999999-0" / "mine.txt", "the user's");
  { OutputFolder output(dir, "c2f-test", {"summary.txt"}); }
  CHECK(read_text(root / ".out.c2f-staging-999999999-0" / "mine.txt") == "the user's");
}

TEST_CASE("OutputFolder without a commit leaves the folder and other outputs as they were",
          "[output]") {
  const fs::path root = fresh("c2f-test-output-folder-failed");
  const fs::path dir = root / "out";
  {
    OutputFolder first(dir, "c2f-test", {"summary.txt"});
    write_text(first.staging() / "summary.txt", "earlier run");
    first.commit();
  }
  const fs::path elsewhere = root / "trace.csv";
  write_text(elsewhere, "earlier trace");
  const auto before = contents(dir);
  try {
    OutputFolder output(dir, "c2f-test", {"summary.txt"});
    write_text(output.stage(dir / "summary.txt"), "half of a new summ");
    const fs::path partial = output.stage(elsewhere);
    CHECK(partial != elsewhere);
    write_text(partial, "half a tra");
    throw std::runtime_error("the run failed");
  } catch (const std::runtime_error&) {
  }
  CHECK(contents(dir) == before);
  CHECK(read_text(elsewhere) == "earlier trace");
  CHECK(contents(root).size() == before.size() + 2);  // out/, its files and the trace: no partial
  CHECK(c2f::test::run_leftovers(dir) == 0);
  {
    OutputFolder output(dir, "c2f-test", {});
    CHECK(output.stage("/dev/null") == fs::path("/dev/null"));  // devices are written in place
  }
  std::ofstream full("/dev/full");
  full << std::string(1 << 16, 'x');
  CHECK_THROWS_WITH(c2f::close_checked(full, "the test stream"),
                    Catch::Contains("writing the test stream failed"));
}

TEST_CASE("OutputFolder writes only folders its tool owns", "[output]") {
  const fs::path root = fresh("c2f-test-output-folder-owner");
  fs::create_directories(root / "users");
  write_text(root / "users" / "error.png", "the user's picture");
  CHECK_THROWS_WITH(OutputFolder(root / "users", "c2f-test", {"error.png"}),
                    Catch::Contains("'" + (root / "users").string() + "' is not empty") &&
                        Catch::Contains("not written by a c2f tool"));
  CHECK(read_text(root / "users" / "error.png") == "the user's picture");

  {
    OutputFolder other(root / "other", "c2f-other", {"a.txt"});
    write_text(other.staging() / "a.txt", "other's");
    other.commit();
  }
  CHECK_THROWS_WITH(OutputFolder(root / "other", "c2f-test", {"a.txt"}),
                    Catch::Contains("holds the outputs of c2f-other, not of c2f-test"));

  // An empty folder is taken, and given back empty when the run fails.
  fs::create_directories(root / "empty");
  { OutputFolder adopted(root / "empty", "c2f-test", {"a.txt"}); }
  CHECK(fs::is_empty(root / "empty"));
  // A folder the run created goes again when the run fails.
  { OutputFolder created(root / "new" / "deeper", "c2f-test", {"a.txt"}); }
  CHECK_FALSE(fs::exists(root / "new" / "deeper"));
}

TEST_CASE("OutputFolder lets one run at a time write a folder", "[output]") {
  const fs::path dir = fresh("c2f-test-output-folder-lock") / "out";
  {
    OutputFolder first(dir, "c2f-test", {"a.txt"});
    CHECK_THROWS_WITH(OutputFolder(dir, "c2f-test", {"a.txt"}),
                      Catch::Contains("is being written by another run (c2f-test, process " +
                                      std::to_string(::getpid()) + ")"));
    write_text(first.staging() / "a.txt", "first");
    first.commit();
    // Still held after the commit, by the marker carried into the new folder.
    CHECK_THROWS_WITH(OutputFolder(dir, "c2f-test", {"a.txt"}),
                      Catch::Contains("is being written by another run"));
  }
  {
    OutputFolder second(dir, "c2f-test", {"a.txt"});  // free again
  }
  // Runs sharing a folder by files stage side by side and commit one after the other.
  {
    OutputFolder a(dir, "c2f-test", {"a.txt"}, OutputFolder::Sharing::by_files);
    OutputFolder b(dir, "c2f-test", {"b.txt"}, OutputFolder::Sharing::by_files);
    write_text(a.staging() / "a.txt", "from a");
    write_text(b.staging() / "b.txt", "from b");
    b.commit();
    a.commit();
  }
  CHECK(read_text(dir / "a.txt") == "from a");
  CHECK(read_text(dir / "b.txt") == "from b");
  // A sharing run waits for a run holding the folder, for a stated time, then gives up.
  {
    OutputFolder holder(dir, "c2f-test", {"a.txt"});
    CHECK_THROWS_WITH(OutputFolder(dir, "c2f-test", {"b.txt"}, OutputFolder::Sharing::by_files,
                                   std::chrono::milliseconds(300)),
                      Catch::Contains("is still being written by another run (c2f-test, process " +
                                      std::to_string(::getpid()) + ") after 0.3 s of waiting"));
  }
}

TEST_CASE("OutputFolder cleans up after killed runs", "[output]") {
  const fs::path root = fresh("c2f-test-output-folder-stale");
  const fs::path dir = root / "out";
  {
    OutputFolder first(dir, "c2f-test", {"summary.txt"});
    write_text(first.staging() / "summary.txt", "committed");
    first.commit();
  }
  // A run killed while it staged (no such process): its staging folder holds the marker's link.
  fs::create_directories(root / ".out.c2f-staging-999999999-0");
  write_text(root / ".out.c2f-staging-999999999-0" / "summary.txt", "from a killed run");
  fs::create_hard_link(dir / c2f::examples::FolderClaim::kMarker,
                       root / ".out.c2f-staging-999999999-0" / c2f::examples::FolderClaim::kMarker);
  { OutputFolder output(dir, "c2f-test", {"summary.txt"}); }
  CHECK_FALSE(fs::exists(root / ".out.c2f-staging-999999999-0"));
  // A run killed between the two renames of a fallback commit: the old folder is put back.
  fs::rename(dir, root / ".out.c2f-retired-999999999-0");
  { OutputFolder output(dir, "c2f-test", {"summary.txt"}); }
  CHECK(read_text(dir / "summary.txt") == "committed");
  CHECK(c2f::test::run_leftovers(dir) == 0);
  // One a live run has aside for a moment (between its two renames) is left alone.
  const fs::path aside = root / (".out.c2f-retired-" + std::to_string(::getpid()) + "-99");
  fs::rename(dir, aside);
  { OutputFolder output(dir, "c2f-test", {"summary.txt"}); }
  CHECK(fs::exists(aside / "summary.txt"));
  CHECK_FALSE(fs::exists(dir));  // created by that run, given back when it failed
}

TEST_CASE("OutputFolder refuses folders it cannot replace and paths inside them", "[output]") {
  const fs::path root = fresh("c2f-test-output-folder-refused");
  CHECK_THROWS_WITH(OutputFolder(fs::current_path(), "c2f-test", {}),
                    Catch::Contains("is the current folder or holds it"));
  CHECK_THROWS_WITH(OutputFolder("/", "c2f-test", {}), Catch::Contains("is the root folder"));
  const fs::path dir = root / "out";
  {
    OutputFolder first(dir, "c2f-test", {"a.txt"});
    first.commit();
  }
  REQUIRE(::mkfifo((dir / "pipe").c_str(), 0600) == 0);
  CHECK_THROWS_WITH(OutputFolder(dir, "c2f-test", {"a.txt"}),
                    Catch::Contains("pipe' , which is not a file") ||
                        Catch::Contains("which is not a file, folder or symbolic link"));
  fs::remove(dir / "pipe");
  OutputFolder output(dir, "c2f-test", {"a.txt"});
  fs::create_directories(dir / "sub");
  CHECK_THROWS_WITH(output.stage(dir / "sub" / "trace.csv"),
                    Catch::Contains("lies in a folder inside the output folder"));
  CHECK(c2f::examples::with_target_paths("cannot write '" + output.staging().string() +
                                         "/summary.txt'") ==
        "cannot write '" + dir.string() + "/summary.txt'");
}

TEST_CASE("StagedFile replaces the file a link names, and refuses a FIFO without reader",
          "[output]") {
  const fs::path root = fresh("c2f-test-staged-file");
  write_text(root / "real.csv", "old");
  fs::create_symlink(root / "real.csv", root / "link.csv");
  {
    c2f::examples::StagedFile file(root / "link.csv");
    CHECK_FALSE(file.in_place());
    write_text(file.path(), "new");
    CHECK(read_text(root / "real.csv") == "old");
    file.commit();
  }
  CHECK(fs::is_symlink(root / "link.csv"));
  CHECK(read_text(root / "real.csv") == "new");
  { c2f::examples::StagedFile abandoned(root / "real.csv"); }
  CHECK(contents(root).size() == 2);  // no partial file left

  REQUIRE(::mkfifo((root / "fifo").c_str(), 0600) == 0);
  CHECK_THROWS_WITH(c2f::examples::StagedFile(root / "fifo"),
                    Catch::Contains("is a FIFO that no process is reading"));
  CHECK_THROWS_WITH(c2f::examples::StagedFile(root), Catch::Contains("is a folder, not a file"));
  CHECK(c2f::examples::StagedFile("/dev/null").in_place());
  // A link to nothing is neither replaced nor followed into a new file.
  fs::create_symlink(root / "nowhere.csv", root / "dangling.csv");
  CHECK_THROWS_WITH(c2f::examples::StagedFile(root / "dangling.csv"),
                    Catch::Contains("dangling.csv' is a symbolic link to '") &&
                        Catch::Contains("nowhere.csv', which does not exist"));
  CHECK(fs::is_symlink(root / "dangling.csv"));
}

TEST_CASE("restore_retired_folder puts a folder back only where none stands", "[output]") {
  const fs::path root = fresh("c2f-test-restore-retired");
  fs::create_directories(root / "aside");
  fs::create_directories(root / "standing");
  CHECK_FALSE(c2f::examples::restore_retired_folder(root / "aside", root / "standing"));
  CHECK(c2f::examples::restore_retired_folder(root / "aside", root / "out"));
  CHECK(fs::is_directory(root / "out"));
}
