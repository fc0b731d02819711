#include "c2f/core/text_input.hpp"

#include <cstdio>

namespace c2f {

std::string_view without_byte_order_mark(std::string_view text) noexcept {
  constexpr std::string_view kMark = "\xEF\xBB\xBF";
  if (text.substr(0, kMark.size()) == kMark) text.remove_prefix(kMark.size());
  return text;
}

bool is_gzip(std::string_view text) noexcept {
  return text.size() >= 2 && static_cast<unsigned char>(text[0]) == 0x1F &&
         static_cast<unsigned char>(text[1]) == 0x8B;
}

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string shown;
  const bool cut = text.size() > max_bytes;
  for (const char c : text.substr(0, max_bytes)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
      shown += escaped;
    } else {
      shown += c;
    }
  }
  if (cut) shown += "...";
  return shown;
}

}  // namespace c2f
