// c2f-plot (built with the benchmarks): traces holding values a plot cannot show are an error
// naming the file, the line and the value, not a crash.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>

#include "support/run_tool.hpp"

TEST_CASE("c2f-plot refuses traces with non-finite or unplottable values", "[plot][cli]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-plot";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string header = "time_s,level,step,energy,num_vars\n";
  auto trace = [&](const std::string& name, const std::string& rows) {
    const auto path = dir / name;
    std::ofstream(path) << header << rows;
    return path.string();
  };
  const std::string good = trace("good.csv", "0.1,0,0,10,4\n0.2,0,1,8,4\n");
  for (const auto& [name, rows, expected] :
       {std::tuple{"nan.csv", "0.1,0,0,nan,4\n", "energy 'nan' is not a finite number"},
        std::tuple{"inf.csv", "0.1,0,0,10,4\ninf,0,1,8,4\n", "time_s 'inf' is not a time"},
        std::tuple{"huge.csv", "0.1,0,0,1e308,4\n0.2,0,1,-1e308,4\n",
                   "energy '1e308' is not a finite number within +-1e300"},
        std::tuple{"garbage.csv", "0.1,0,0,10x,4\n", "energy '10x'"}}) {
    const auto r = c2f::test::run_tool(
        C2F_PLOT_BINARY, "-o " + (dir / "plot.png").string() + " a=" + trace(name, rows));
    INFO(name << ": " << r.output);
    CHECK(r.exit_code != 0);
    CHECK(r.exit_code != -1);  // not killed by a signal
    CHECK_THAT(r.output, Catch::Contains(name) && Catch::Contains(expected));
  }
  const auto ok =
      c2f::test::run_tool(C2F_PLOT_BINARY, "-o " + (dir / "plot.png").string() + " a=" + good);
  CHECK(ok.exit_code == 0);
  CHECK(std::filesystem::exists(dir / "plot.png"));
}
