#pragma once
// Reading text that people make: a UTF-8 byte-order mark some editors put first, compressed
// files given where text is expected, and control bytes that must not reach an error message
// raw.

#include <cstddef>
#include <string>
#include <string_view>

namespace c2f {

/// `text` without a leading UTF-8 byte-order mark (EF BB BF), which carries no content.
std::string_view without_byte_order_mark(std::string_view text) noexcept;

/// Whether `text` starts with the gzip magic bytes (1F 8B): a compressed file, not text.
bool is_gzip(std::string_view text) noexcept;

/// `text` as it can be shown inside an error message: control bytes (a NUL, an escape, C1
/// controls) and bytes that are no well-formed UTF-8 as \xNN, well-formed UTF-8 as it is, and
/// text longer than `max_bytes` cut with "...".
std::string printable(std::string_view text, std::size_t max_bytes = 60);

}  // namespace c2f
