// Numbers are written in the "C" locale whatever locale the process has set: model files, traces
// and reports read back the same in a program that called setlocale (Python after
// locale.setlocale(locale.LC_ALL, "")). Run under de_DE.UTF-8, whose decimal separator is a
// comma; scripts/install-deps generates it.

#include <catch2/catch.hpp>

#include <clocale>
#include <sstream>
#include <string>

#include "c2f/core/uai.hpp"
#include "c2f/driver/observer.hpp"
#include "c2f/driver/trace.hpp"
#include "c2f/support/number_text.hpp"
#include "support/random_models.hpp"

using namespace c2f;

namespace {

/// Sets the comma-decimal locale for the process while it lives, and the "C" locale after.
struct CommaLocale {
  CommaLocale() {
    const char* set = std::setlocale(LC_ALL, "de_DE.UTF-8");
    INFO("the de_DE.UTF-8 locale is missing: run scripts/install-deps");
    REQUIRE(set != nullptr);
    char text[16];
    std::snprintf(text, sizeof text, "%.1f", 0.5);
    REQUIRE(std::string(text) == "0,5");  // the locale really writes commas
  }
  ~CommaLocale() { std::setlocale(LC_ALL, "C"); }
};

}  // namespace

TEST_CASE("c_format writes decimal points under a comma locale", "[locale]") {
  const CommaLocale comma;
  CHECK(c_format("%.6f|%.17g|%g|%.2f%%", 0.5, 0.1, 1e-5, 12.345) ==
        "0.500000|0.10000000000000001|1e-05|12.35%");
  CHECK(format_real(2.5) == "2.5");
  CHECK(c_format("%s %d", std::string(300, 'x').c_str(), 7) == std::string(300, 'x') + " 7");
}

TEST_CASE("UAI files and traces written under a comma locale read back", "[locale][uai]") {
  test::Rng rng(11);
  const PairwiseEnergy energy = test::random_energy(rng, 6, 3, 5);
  std::string text;
  {
    const CommaLocale comma;
    std::ostringstream file;
    write_uai(energy, file);
    text = file.str();
    CHECK(text.find(',') == std::string::npos);
    std::ostringstream trace;
    TraceWriter writer(trace, {}, "trace.csv");
    StepEvent event;
    event.time_s = 0.25;
    event.energy = 1.5;
    writer(event);
    CHECK(trace.str().find("0.250000,0,0,1.5,") != std::string::npos);
  }
  std::istringstream back(text);
  const PairwiseEnergy read = read_uai(back, "written under de_DE");
  CHECK(read.num_variables() == energy.num_variables());
}
