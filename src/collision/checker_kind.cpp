#include "pmdplan/collision/checker_kind.hpp"

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

std::string checkerKindName(CheckerKind kind) { return kind == CheckerKind::Exact ? "exact" : "fast"; }

std::optional<CheckerKind> parseCheckerKind(std::string_view text) {
  if (text == "exact") return CheckerKind::Exact;
  if (text == "fast") return CheckerKind::Fast;
  return std::nullopt;
}

CheckerKind checkerKindNamed(std::string_view text, const std::string& field) {
  const std::optional<CheckerKind> kind = parseCheckerKind(text);
  if (!kind) throw InputError("", field, "'" + std::string(text) + "' is not a checker; expected exact or fast");
  return *kind;
}

}  // namespace pmdplan
