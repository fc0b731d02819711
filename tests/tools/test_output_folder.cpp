// OutputFolder: a run's files land together or not at all, stale files the run owns go, other
// files stay.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "c2f/core/output_file.hpp"
#include "output_folder.hpp"

namespace {

namespace fs = std::filesystem;

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST_CASE("OutputFolder commits staged files and removes only stale owned ones", "[output]") {
  const fs::path dir = fs::temp_directory_path() / "c2f-test-output-folder";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_text(dir / "summary.txt", "old summary");
  write_text(dir / "partition-level0.png", "old picture");
  write_text(dir / "notes.txt", "the user's own file");
  {
    c2f::examples::OutputFolder output(dir, {"summary.txt", "trace.csv", "partition-level*.png"});
    CHECK(output.owns("partition-level12.png"));
    CHECK_FALSE(output.owns("notes.txt"));
    write_text(output.stage(dir / "summary.txt"), "new summary");
    write_text(output.stage(dir / "trace.csv"), "new trace");
    CHECK(read_text(dir / "summary.txt") == "old summary");  // nothing moves before commit
    const auto moved = output.commit();
    CHECK(moved.size() == 2);
  }
  CHECK(read_text(dir / "summary.txt") == "new summary");
  CHECK(read_text(dir / "trace.csv") == "new trace");
  CHECK_FALSE(fs::exists(dir / "partition-level0.png"));  // owned, not written this time
  CHECK(read_text(dir / "notes.txt") == "the user's own file");
  for (const auto& entry : fs::directory_iterator(dir))  // no staging folder left
    CHECK(entry.path().filename().string().rfind(".c2f-staging", 0) != 0);
}

TEST_CASE("OutputFolder without a commit leaves the folder as it was", "[output]") {
  const fs::path dir = fs::temp_directory_path() / "c2f-test-output-folder-failed";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_text(dir / "summary.txt", "earlier run");
  const fs::path elsewhere = fs::temp_directory_path() / "c2f-test-output-elsewhere.csv";
  write_text(elsewhere, "earlier trace");
  try {
    c2f::examples::OutputFolder output(dir, {"summary.txt"});
    write_text(output.stage(dir / "summary.txt"), "half of a new summ");
    const fs::path partial = output.stage(elsewhere);
    CHECK(partial != elsewhere);
    write_text(partial, "half a tra");
    throw std::runtime_error("the run failed");
  } catch (const std::runtime_error&) {
  }
  CHECK(read_text(dir / "summary.txt") == "earlier run");
  CHECK(read_text(elsewhere) == "earlier trace");
  CHECK_FALSE(fs::exists(fs::path(elsewhere.string() + ".c2f-partial")));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  CHECK(entries == 1);
  {
    c2f::examples::OutputFolder output(dir, {});
    CHECK(output.stage("/dev/null") == fs::path("/dev/null"));  // devices are written directly
  }
  std::ofstream full("/dev/full");
  full << std::string(1 << 16, 'x');
  CHECK_THROWS_WITH(c2f::close_checked(full, "the test stream"),
                    Catch::Contains("writing the test stream failed"));
}

TEST_CASE("OutputFolder removes staging folders that killed runs left behind", "[output]") {
  const fs::path dir = fs::temp_directory_path() / "c2f-test-output-folder-stale";
  fs::remove_all(dir);
  fs::create_directories(dir / ".c2f-staging-999999999");  // no such process
  write_text(dir / ".c2f-staging-999999999" / "summary.txt", "from a killed run");
  { c2f::examples::OutputFolder output(dir, {"summary.txt"}); }
  CHECK_FALSE(fs::exists(dir / ".c2f-staging-999999999"));
}

TEST_CASE("OutputFolder without a commit removes the folder it created", "[output]") {
  const fs::path root = fs::temp_directory_path() / "c2f-test-output-created";
  fs::remove_all(root);
  fs::create_directories(root / "existing");
  {
    c2f::examples::OutputFolder fresh(root / "fresh", {"a.txt"});
    write_text(fresh.staging() / "a.txt", "never committed");
    c2f::examples::OutputFolder existing(root / "existing", {"a.txt"});
  }
  CHECK_FALSE(fs::exists(root / "fresh"));     // created by the run, which failed
  CHECK(fs::is_directory(root / "existing"));  // the user's folder stays, even empty
  {
    c2f::examples::OutputFolder fresh(root / "fresh", {"a.txt"});
    write_text(fresh.staging() / "a.txt", "committed");
    fresh.commit();
  }
  CHECK(fs::exists(root / "fresh" / "a.txt"));
}
