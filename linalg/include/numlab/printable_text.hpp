#pragma once
// Text from outside (file contents, file names, command-line words) made safe to echo in a message.
// Printable ASCII and well-formed, visible UTF-8 pass through. Control bytes (escape sequences, bells,
// carriage returns), C1 controls, invisible marks (a byte-order mark, direction overrides) and bytes
// that are not well-formed UTF-8 become \xNN, so an error line stays one line and cannot retitle or
// redraw the user's terminal.

#include <cstddef>
#include <string>
#include <string_view>

namespace numlab {

namespace detail {

// Length of the well-formed UTF-8 sequence starting at text[i] that is safe to print, or 0.
inline std::size_t printable_utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  char32_t code = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    code = lead & 0x1Fu;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    code = lead & 0x0Fu;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    code = lead & 0x07u;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0u) != 0x80u) return 0;
    code = (code << 6) | (byte(i + k) & 0x3Fu);
  }
  const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
  const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
  const bool c1_control = code >= 0x80 && code <= 0x9F;
  const bool beyond_unicode = code > 0x10FFFF;
  // Invisible marks and direction overrides would hide or reorder what the message shows.
  const bool invisible = code == 0xFEFF || (code >= 0x200B && code <= 0x200F) || (code >= 0x202A && code <= 0x202E) ||
                         (code >= 0x2066 && code <= 0x2069);
  return overlong || surrogate || c1_control || beyond_unicode || invisible ? 0 : length;
}

}  // namespace detail

inline std::string printable(std::string_view text) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string safe;
  safe.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x20 && byte < 0x7F) {
      safe += static_cast<char>(byte);
      ++i;
    } else if (const std::size_t length = detail::printable_utf8_length(text, i); length > 0) {
      safe.append(text.substr(i, length));
      i += length;
    } else {
      safe += "\\x";
      safe += hex[byte >> 4];
      safe += hex[byte & 0x0F];
      ++i;
    }
  }
  return safe;
}

}  // namespace numlab
