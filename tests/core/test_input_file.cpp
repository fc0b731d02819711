// The input layer: a path is read only when it is a regular file of bounded size, and a FIFO
// without a writer, a device or a folder is refused by name at once instead of blocking or
// reading until memory runs out.

#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "c2f/core/memory_budget.hpp"
#include "c2f/core/uai.hpp"
#include "c2f/support/input_file.hpp"

using namespace c2f;
namespace fs = std::filesystem;

namespace {

/// A fresh folder under the system's temporary folder, removed with its contents.
struct TemporaryFolder {
  fs::path path = fs::temp_directory_path() /
                  ("c2f-input-" + std::to_string(::getpid()) + "-" +
                   std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
  TemporaryFolder() { fs::create_directories(path); }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

std::string refusal(const std::string& path, std::size_t max_bytes) {
  try {
    read_input_file(path, "trace", max_bytes);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("the input layer reads regular files and refuses the rest by name", "[input]") {
  const TemporaryFolder folder;
  const std::string text = (folder.path / "trace.csv").string();
  std::ofstream(text) << "time_s,level\n0.5,0\n";
  CHECK(read_input_file(text, "trace", 1024) == "time_s,level\n0.5,0\n");
  CHECK(refusal(text, 10) ==
        "trace '" + text + "' is 19 bytes; a trace of at most 10 bytes is expected");

  const std::string fifo = (folder.path / "pipe").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const auto start = std::chrono::steady_clock::now();
  CHECK(refusal(fifo, 1024) == "trace '" + fifo + "' is not a regular file (a FIFO)");
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));  // never blocked

  const std::string zero_link = (folder.path / "zero.csv").string();
  fs::create_symlink("/dev/zero", zero_link);
  CHECK(refusal(zero_link, 1024) == "trace '" + zero_link + "' is not a regular file (a device)");
  CHECK(refusal(folder.path.string(), 1024) ==
        "trace '" + folder.path.string() + "' is a folder, not a file");
  CHECK(refusal((folder.path / "missing").string(), 1024) ==
        "trace '" + (folder.path / "missing").string() + "' does not exist");
  CHECK(refusal((folder.path / "trace.csv" / "below").string(), 1024).ends_with("does not exist"));
}

TEST_CASE("a UAI file's declarations are checked against the budget before allocating",
          "[input][uai]") {
  const TemporaryFolder folder;
  // 512 variables of 2^20 labels declare 4 GiB of unary costs in a few kilobytes.
  const std::string model = (folder.path / "huge.uai").string();
  {
    std::ofstream out(model);
    out << "MARKOV\n512\n";
    for (int v = 0; v < 512; ++v) out << "1048576 ";
    out << "\n0\n";
  }
  const MemoryBudget budget = memory_budget_of_gib(0.5, "--memory 0.5");
  try {
    read_uai_file(model, budget);
    FAIL("the model was read");
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    CHECK(message.find(model + " (512 variables x 1048576 labels, 0 factors) needs 4.0 GiB") !=
          std::string::npos);
    CHECK(message.find("--memory 0.5") != std::string::npos);
  }
  const std::string fifo = (folder.path / "model.uai").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(read_uai_file(fifo, budget),
                    "UAI file '" + fifo + "' is not a regular file (a FIFO)");
}
