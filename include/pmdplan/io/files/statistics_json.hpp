#pragma once
// PlanningStatistics as JSON, for the path file and `pmdplan plan --json`: one key per member
// (snake_case, in the order of statisticsJsonKeys(); the timings only when asked for, the hand
// dimensions as {"2": n, ...}, collision_checks = state_checks + motion_checks).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

/// Every key, in the order they are written: status, planning_time_s, smoothing_time_s, ...
const std::vector<const char*>& statisticsJsonKeys();

nlohmann::ordered_json statisticsToJson(const PlanningStatistics& statistics, bool includeTimings);

/// The inverse; timings are optional (0 when absent). Throws InputError naming `file` and
/// `field`.<key> for a missing or unknown key or a wrong type.
PlanningStatistics statisticsFromJson(const nlohmann::json& json, const std::string& file, const std::string& field);

}  // namespace pmdplan
