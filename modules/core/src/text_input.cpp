#include "c2f/support/text_input.hpp"

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

namespace {

/// The length of the well-formed UTF-8 sequence at the start of `text` (1 to 4), or 0 when it
/// starts with a byte that begins none (a stray continuation byte, a cut or overlong sequence,
/// a surrogate).
std::size_t utf8_sequence(std::string_view text) {
  const auto at = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = at(0);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the second byte's range
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (text.size() < length || at(1) < low || at(1) > high) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if (at(i) < 0x80 || at(i) > 0xBF) return 0;
  return length;
}

void escape(unsigned char byte, std::string& shown) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  shown += "\\x";
  shown += kHex[byte >> 4];
  shown += kHex[byte & 0xF];
}

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string shown;
  const bool cut = text.size() > max_bytes;
  text = text.substr(0, max_bytes);
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const std::size_t length = utf8_sequence(text.substr(i));
    // C0 and C1 controls (ESC, CSI U+009B) would reach a terminal as commands; bytes that are
    // no UTF-8 would make the message undecodable (Python raised an empty ValueError).
    const bool c1 = length == 2 && byte == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0;
    if (length == 0 || byte < 0x20 || byte == 0x7F || c1) {
      escape(byte, shown);
      ++i;
      continue;
    }
    shown.append(text.substr(i, length));
    i += length;
  }
  if (cut) shown += "...";
  return shown;
}

}  // namespace c2f
