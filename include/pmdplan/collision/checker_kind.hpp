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

}  // namespace pmdplan
