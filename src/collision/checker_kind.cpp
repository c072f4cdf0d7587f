#include "pmdplan/collision/checker_kind.hpp"

namespace pmdplan {

std::string checkerKindName(CheckerKind kind) { return kind == CheckerKind::Exact ? "exact" : "fast"; }

std::optional<CheckerKind> parseCheckerKind(std::string_view text) {
  if (text == "exact") return CheckerKind::Exact;
  if (text == "fast") return CheckerKind::Fast;
  return std::nullopt;
}

}  // namespace pmdplan
