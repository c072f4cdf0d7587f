#include "pmdplan/io/files/statistics_json.hpp"

#include "json_reading.hpp"

namespace pmdplan {

nlohmann::ordered_json statisticsToJson(const PlanningStatistics& s, bool includeTimings) {
  nlohmann::ordered_json json;
  json["status"] = plannerStatusName(s.status);
  if (includeTimings) {
    json["planning_time_s"] = s.planningTime;
    json["smoothing_time_s"] = s.smoothingTime;
  }
  json["final_rho_a"] = s.finalArmHalfSize;
  json["sweeps"] = s.sweeps;
  json["max_trials"] = s.maxTrials;
  json["samples"] = s.samples;
  json["arm_trials"] = s.armTrials;
  json["roadmap_nodes"] = s.roadmapNodes;
  json["roadmap_edges"] = s.roadmapEdges;
  nlohmann::ordered_json byDimension = nlohmann::ordered_json::object();
  for (const auto& [dimension, count] : s.nodesByHandDimension) byDimension[std::to_string(dimension)] = count;
  json["nodes_by_hand_dimension"] = byDimension;
  json["path_nodes"] = s.pathNodes;
  json["path_nodes_before_smoothing"] = s.pathNodesBeforeSmoothing;
  json["path_length"] = s.pathLength;
  json["path_length_before_smoothing"] = s.pathLengthBeforeSmoothing;
  json["state_checks"] = s.stateChecks;
  json["motion_checks"] = s.motionChecks;
  json["collision_checks"] = s.collisionChecks();
  return json;
}

PlanningStatistics statisticsFromJson(const nlohmann::json& json, const std::string& file, const std::string& field) {
  using namespace json_reading;
  const Place place{file, field};
  requireObject(json, place);
  checkKeys(
      json, place,
      {"status", "planning_time_s", "smoothing_time_s", "final_rho_a", "sweeps", "max_trials", "samples", "arm_trials",
       "roadmap_nodes", "roadmap_edges", "nodes_by_hand_dimension", "path_nodes", "path_nodes_before_smoothing",
       "path_length", "path_length_before_smoothing", "state_checks", "motion_checks", "collision_checks"},
      {"status", "final_rho_a", "sweeps", "max_trials", "samples", "arm_trials", "roadmap_nodes", "roadmap_edges",
       "nodes_by_hand_dimension", "path_nodes", "path_nodes_before_smoothing", "path_length",
       "path_length_before_smoothing", "state_checks", "motion_checks", "collision_checks"});
  PlanningStatistics s;
  const auto count = [&](const char* key) { return readUnsigned(member(json, key), place.key(key)); };
  const auto number = [&](const char* key) { return readFinite(member(json, key), place.key(key)); };

  const std::string status = readString(member(json, "status"), place.key("status"));
  const auto parsed = parsePlannerStatus(status);
  if (!parsed)
    place.key("status").fail("unknown status '" + status + "'; expected solved, time_limit, sample_limit, ...");
  s.status = *parsed;
  if (json.contains("planning_time_s")) s.planningTime = number("planning_time_s");
  if (json.contains("smoothing_time_s")) s.smoothingTime = number("smoothing_time_s");
  s.finalArmHalfSize = number("final_rho_a");
  s.sweeps = count("sweeps");
  s.maxTrials = count("max_trials");
  s.samples = count("samples");
  s.armTrials = count("arm_trials");
  s.roadmapNodes = count("roadmap_nodes");
  s.roadmapEdges = count("roadmap_edges");
  const Place byDimensionPlace = place.key("nodes_by_hand_dimension");
  const nlohmann::json& byDimension = requireObject(member(json, "nodes_by_hand_dimension"), byDimensionPlace);
  for (auto item = byDimension.begin(); item != byDimension.end(); ++item) {
    const std::string& key = item.key();
    const bool digits = !key.empty() && key.size() <= 4 && key.find_first_not_of("0123456789") == std::string::npos;
    if (!digits) byDimensionPlace.key(key).fail("expected a hand dimension (a whole number) as key");
    s.nodesByHandDimension[std::stoi(key)] = readUnsigned(item.value(), byDimensionPlace.key(key));
  }
  s.pathNodes = count("path_nodes");
  s.pathNodesBeforeSmoothing = count("path_nodes_before_smoothing");
  s.pathLength = number("path_length");
  s.pathLengthBeforeSmoothing = number("path_length_before_smoothing");
  s.stateChecks = count("state_checks");
  s.motionChecks = count("motion_checks");
  if (count("collision_checks") != s.collisionChecks())
    place.key("collision_checks")
        .fail("must equal state_checks + motion_checks (" + std::to_string(s.collisionChecks()) + ")");
  return s;
}

}  // namespace pmdplan
