#include "pmdplan/collision/collision_report.hpp"

namespace pmdplan {

std::string pairsText(const CollisionReport& report) {
  std::string text;
  for (const auto& [a, b] : report.pairs) text += (text.empty() ? "" : ", ") + a + " - " + b;
  return text;
}

}  // namespace pmdplan
