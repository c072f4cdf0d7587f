#pragma once
// PlanningStatistics as JSON, for the path file and `pmdplan plan --json`. Keys (snake_case, in
// this order): status, planning_time_s and smoothing_time_s (only with timings), final_rho_a,
// sweeps, max_trials, samples, hand_arm_samples, roadmap_nodes, roadmap_edges,
// nodes_by_hand_dimension ({"2": n, ...}), path_nodes, path_nodes_before_smoothing, path_length,
// path_length_before_smoothing, state_checks, motion_checks, collision_checks.
#include <nlohmann/json.hpp>
#include <string>

#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

nlohmann::ordered_json statisticsToJson(const PlanningStatistics& statistics, bool includeTimings);

/// The inverse; timings are optional (0 when absent). Throws InputError naming `file` and
/// `field`.<key> for a missing or unknown key or a wrong type.
PlanningStatistics statisticsFromJson(const nlohmann::json& json, const std::string& file, const std::string& field);

}  // namespace pmdplan
