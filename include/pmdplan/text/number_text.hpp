#pragma once
// Numbers in our text files: written in the shortest form that reads back to the same double, so
// files round-trip exactly and the same values always give the same bytes.
#include <optional>
#include <string>
#include <string_view>

namespace pmdplan {

/// Shortest decimal text that parses back to exactly `value` ("0.1", "1e-05", "42").
std::string exactNumberText(double value);

/// `value` to six significant digits, for messages ("89.99998" -> "90").
std::string messageNumberText(double value);

/// A finite decimal number (optional sign, digits, point, exponent), surrounding blanks allowed;
/// nullopt for anything else, including inf and nan.
std::optional<double> parseFiniteNumber(std::string_view text);

/// A whole number with no sign, point or exponent, surrounding blanks allowed; nullopt otherwise.
std::optional<long long> parseWholeNumber(std::string_view text);

}  // namespace pmdplan
