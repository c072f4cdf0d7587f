#include "pmdplan/io/files/path_validation_json.hpp"

namespace pmdplan {

nlohmann::ordered_json pathValidationJson(const PathValidation& validation, const PathPhases& phases,
                                          double toleranceMm) {
  auto pairs = nlohmann::ordered_json::array();
  for (const auto& [a, b] : validation.collisions.pairs) pairs.push_back({a, b});
  return {{"valid", validation.valid},
          {"states_checked", validation.statesChecked},
          {"tolerance_mm", toleranceMm},
          {"closing_from", phases.closingFrom ? nlohmann::ordered_json(*phases.closingFrom) : nlohmann::ordered_json()},
          {"collisions", std::move(pairs)},
          {"problems", validation.problems}};
}

}  // namespace pmdplan
