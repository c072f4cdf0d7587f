#pragma once
// A path's judgement by the grasp rule (GraspRule::validatePath, collision/grasp_rule.hpp) as
// JSON, the one form `pmdplan validate --json` prints, Python's pmdplan.validate returns and the
// viewer data holds for each path: {valid, states_checked, tolerance_mm, closing_from (the
// closing phase's first point, or null), collisions: [[a, b], ...], problems: [text, ...]}.
#include <nlohmann/json.hpp>

#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/collision/path_validation.hpp"

namespace pmdplan {

nlohmann::ordered_json pathValidationJson(const PathValidation& validation, const PathPhases& phases,
                                          double toleranceMm);

}  // namespace pmdplan
