#pragma once
// Which collision checker a planner runs on: the exact checker, or the fast convex-part checker
// (capsules and boxes screened in SIMD lanes) whose answers equal it (flagged pairs confirmed by
// the exact one).
#include <optional>
#include <string>
#include <string_view>

namespace pmdplan {

enum class CheckerKind { Exact, Fast };

std::string checkerKindName(CheckerKind kind);
/// "exact" or "fast"; nothing for any other text.
std::optional<CheckerKind> parseCheckerKind(std::string_view text);
/// parseCheckerKind, or InputError (no file, the given field: "--checker" on the command line,
/// "checker" in Python) saying what the text is not and what is expected.
CheckerKind checkerKindNamed(std::string_view text, const std::string& field);

}  // namespace pmdplan
