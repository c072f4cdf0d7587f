#pragma once
// How messages show text that came from a file or a command line (docs/robustness.md): nothing is
// printed raw. Control characters, invisible format characters and bytes that are not UTF-8 are
// written as escapes, and a value longer than kMaxQuotedBytes or spanning lines is described by
// its length, so an error never shows a file's contents (a secret read by mistake, a terminal
// escape sequence).
#include <cstddef>
#include <string>
#include <string_view>

namespace pmdplan {

/// The longest value a message quotes (in bytes); a longer one is described by its length.
constexpr std::size_t kMaxQuotedBytes = 40;

/// `text` with every byte a terminal could act on written as an escape: \n, \r, \t, \xNN for the
/// other C0 controls, DEL and bytes that are not UTF-8, \uNNNN for C1 controls and invisible
/// format characters (bidirectional overrides, zero-width characters, the byte order mark).
/// Backslashes stay as they are, so escaping an escaped text changes nothing.
std::string escapedText(std::string_view text);

/// A value for a message: 'text', escaped, when it has at most kMaxQuotedBytes bytes on one line;
/// otherwise "a text of N characters".
std::string quotedText(std::string_view text);

/// A key or column name as a step of a field path (`obstacles[2].box`): the key itself, escaped,
/// when it has at most kMaxQuotedBytes bytes on one line; otherwise "<a key of N characters>".
std::string fieldKeyText(std::string_view key);

}  // namespace pmdplan
