#include "pmdplan/core/message_text.hpp"

#include <cstdint>
#include <cstdio>

namespace pmdplan {
namespace {

std::string hexEscape(unsigned char byte) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "\\x%02x", byte);
  return buffer;
}

std::string unicodeEscape(std::uint32_t codePoint) {
  char buffer[12];
  std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(codePoint));
  return buffer;
}

/// Code points a terminal shows as nothing or uses to reorder text: C1 controls, zero-width and
/// bidirectional formatting characters, line and paragraph separators, the byte order mark.
bool isInvisible(std::uint32_t c) {
  return (c >= 0x80 && c <= 0x9f) || c == 0xad || (c >= 0x200b && c <= 0x200f) || (c >= 0x2028 && c <= 0x202e) ||
         (c >= 0x2060 && c <= 0x206f) || c == 0xfeff;
}

/// The length of the well-formed UTF-8 sequence at text[i] (2 to 4) and its code point, or 0 if
/// the bytes there are not one (a stray continuation byte, an overlong form, a surrogate).
std::size_t utf8Sequence(std::string_view text, std::size_t i, std::uint32_t& codePoint) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
  const unsigned char lead = byte(0);
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xbf;  // the allowed range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
    codePoint = lead & 0x1fu;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    codePoint = lead & 0x0fu;
    if (lead == 0xe0) low = 0xa0;   // overlong
    if (lead == 0xed) high = 0x9f;  // surrogates
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    codePoint = lead & 0x07u;
    if (lead == 0xf0) low = 0x90;   // overlong
    if (lead == 0xf4) high = 0x8f;  // beyond U+10FFFF
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    const unsigned char next = byte(k);
    if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xbf)) return 0;
    codePoint = (codePoint << 6) | (next & 0x3fu);
  }
  return length;
}

bool isOneShortLine(std::string_view text) {
  return text.size() <= kMaxQuotedBytes && text.find('\n') == std::string_view::npos;
}

}  // namespace

std::string escapedText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x20 && byte < 0x7f) {
      out.push_back(text[i++]);
    } else if (byte == '\n' || byte == '\r' || byte == '\t') {
      out += byte == '\n' ? "\\n" : byte == '\r' ? "\\r" : "\\t";
      ++i;
    } else if (byte < 0x80) {
      out += hexEscape(byte);
      ++i;
    } else {
      std::uint32_t codePoint = 0;
      const std::size_t length = utf8Sequence(text, i, codePoint);
      if (length == 0) {
        out += hexEscape(byte);
        ++i;
      } else {
        if (isInvisible(codePoint))
          out += unicodeEscape(codePoint);
        else
          out.append(text.substr(i, length));
        i += length;
      }
    }
  }
  return out;
}

std::string quotedText(std::string_view text) {
  if (!isOneShortLine(text)) return "a text of " + std::to_string(text.size()) + " characters";
  std::string result(1, '\'');  // built by appending: GCC 12 warns falsely on "'" + string
  result += escapedText(text);
  result.push_back('\'');
  return result;
}

std::string fieldKeyText(std::string_view key) {
  if (!isOneShortLine(key)) return "<a key of " + std::to_string(key.size()) + " characters>";
  return escapedText(key);
}

}  // namespace pmdplan
