// Text that people make: a byte-order mark first, a compressed file where text is expected,
// control bytes that must reach an error message escaped.

#include <catch2/catch.hpp>

#include <sstream>
#include <stdexcept>
#include <string>

#include "c2f/core/uai.hpp"
#include "c2f/support/text_input.hpp"

using namespace c2f;

TEST_CASE("text helpers: byte-order mark, gzip, printable", "[text]") {
  CHECK(without_byte_order_mark("\xEF\xBB\xBFMARKOV") == "MARKOV");
  CHECK(without_byte_order_mark("MARKOV") == "MARKOV");
  CHECK(without_byte_order_mark("\xEF\xBB") == "\xEF\xBB");  // a partial mark is content
  CHECK(is_gzip(std::string("\x1F\x8B\x08", 3)));
  CHECK_FALSE(is_gzip("MARKOV"));
  CHECK_FALSE(is_gzip("\x1F"));
  CHECK(printable(std::string("a\0b\x1B", 4)) == "a\\x00b\\x1B");
  CHECK(printable("caf\xC3\xA9") == "caf\xC3\xA9");  // UTF-8 stays
  CHECK(printable(std::string(100, 'x'), 10) == "xxxxxxxxxx...");
  // Bytes that are no UTF-8, and C1 controls (CSI, U+009B), are escaped; a message stays text.
  CHECK(printable("\xFF"
                  "caf\xC3\xA9 \xC2\x9B[2J \xE2\x82") ==
        "\\xFFcaf\xC3\xA9 \\xC2\\x9B[2J \\xE2\\x82");
  CHECK(printable("\xED\xA0\x80") == "\\xED\\xA0\\x80");  // a surrogate
}

TEST_CASE("UAI text with a byte-order mark reads; compressed or binary text is refused clearly",
          "[text][uai]") {
  const std::string model = "MARKOV\n1\n2\n1\n1 0\n2\n0.5 0.25\n";
  std::istringstream plain(model), marked("\xEF\xBB\xBF" + model);
  CHECK(read_uai(marked, "marked.uai").evaluate(Labeling{1}) ==
        read_uai(plain, "plain.uai").evaluate(Labeling{1}));

  auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      (void)read_uai(in, "m.uai");
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error_of(std::string("\x1F\x8B\x08\0\0\0", 6) + "rest"),
             Catch::Contains("m.uai: a gzip-compressed file, not UAI text: decompress it first"));
  // A NUL inside a token is shown escaped, and the message goes on past it.
  const std::string with_nul = error_of(std::string("MAR\0KOV\n1\n2\n", 11));
  CHECK_THAT(with_nul, Catch::Contains("network type 'MAR\\x00KOV' is not supported"));
}
