#include "pmdplan/io/files/statistics_json.hpp"

#include "json_reading.hpp"
#include "pmdplan/core/message_text.hpp"

namespace pmdplan {
namespace {

using S = PlanningStatistics;

/// One key of the statistics JSON; the table below is its only list (writing, reading, the help).
struct StatisticsField {
  enum class Kind { Status, Timing, Number, Count, ByDimension, CollisionChecks };
  const char* key;
  Kind kind;
  double S::*number = nullptr;      ///< Timing and Number
  std::size_t S::*count = nullptr;  ///< Count
};

using K = StatisticsField::Kind;
const StatisticsField kFields[] = {
    {"status", K::Status},
    {"planning_time_s", K::Timing, &S::planningTime},
    {"smoothing_time_s", K::Timing, &S::smoothingTime},
    {"final_rho_a", K::Number, &S::finalArmHalfSize},
    {"sweeps", K::Count, nullptr, &S::sweeps},
    {"max_trials", K::Count, nullptr, &S::maxTrials},
    {"samples", K::Count, nullptr, &S::samples},
    {"arm_trials", K::Count, nullptr, &S::armTrials},
    {"roadmap_nodes", K::Count, nullptr, &S::roadmapNodes},
    {"roadmap_edges", K::Count, nullptr, &S::roadmapEdges},
    {"nodes_by_hand_dimension", K::ByDimension},
    {"path_nodes", K::Count, nullptr, &S::pathNodes},
    {"path_nodes_before_smoothing", K::Count, nullptr, &S::pathNodesBeforeSmoothing},
    {"path_length", K::Number, &S::pathLength},
    {"path_length_before_smoothing", K::Number, &S::pathLengthBeforeSmoothing},
    {"state_checks", K::Count, nullptr, &S::stateChecks},
    {"motion_checks", K::Count, nullptr, &S::motionChecks},
    {"collision_checks", K::CollisionChecks},
};

}  // namespace

const std::vector<const char*>& statisticsJsonKeys() {
  static const std::vector<const char*> keys = [] {
    std::vector<const char*> all;
    for (const StatisticsField& field : kFields) all.push_back(field.key);
    return all;
  }();
  return keys;
}

nlohmann::ordered_json statisticsToJson(const PlanningStatistics& s, bool includeTimings) {
  nlohmann::ordered_json json;
  for (const StatisticsField& field : kFields) {
    switch (field.kind) {
      case K::Status:
        json[field.key] = plannerStatusName(s.status);
        break;
      case K::Timing:
        if (includeTimings) json[field.key] = s.*field.number;
        break;
      case K::Number:
        json[field.key] = s.*field.number;
        break;
      case K::Count:
        json[field.key] = s.*field.count;
        break;
      case K::ByDimension: {
        nlohmann::ordered_json byDimension = nlohmann::ordered_json::object();
        for (const auto& [dimension, count] : s.nodesByHandDimension) byDimension[std::to_string(dimension)] = count;
        json[field.key] = byDimension;
        break;
      }
      case K::CollisionChecks:
        json[field.key] = s.collisionChecks();
        break;
    }
  }
  return json;
}

PlanningStatistics statisticsFromJson(const nlohmann::json& json, const std::string& file, const std::string& field) {
  using namespace json_reading;
  const Place place{file, field};
  requireObject(json, place);
  std::vector<const char*> required;
  for (const StatisticsField& f : kFields)
    if (f.kind != K::Timing) required.push_back(f.key);
  checkKeys(json, place, statisticsJsonKeys(), required);
  PlanningStatistics s;
  for (const StatisticsField& f : kFields) {
    const Place at = place.key(f.key);
    switch (f.kind) {
      case K::Status: {
        const std::string status = readString(member(json, f.key), at);
        const auto parsed = parsePlannerStatus(status);
        if (!parsed)
          at.fail("unknown status " + quotedText(status) + "; expected solved, time_limit, sample_limit, ...");
        s.status = *parsed;
        break;
      }
      case K::Timing:
        if (json.contains(f.key)) s.*f.number = readFinite(member(json, f.key), at);
        break;
      case K::Number:
        s.*f.number = readFinite(member(json, f.key), at);
        break;
      case K::Count:
        s.*f.count = readUnsigned(member(json, f.key), at);
        break;
      case K::ByDimension: {
        const nlohmann::json& byDimension = requireObject(member(json, f.key), at);
        for (auto item = byDimension.begin(); item != byDimension.end(); ++item) {
          const std::string& key = item.key();
          const bool digits =
              !key.empty() && key.size() <= 4 && key.find_first_not_of("0123456789") == std::string::npos;
          if (!digits) at.key(key).fail("expected a hand dimension (a whole number) as key");
          s.nodesByHandDimension[std::stoi(key)] = readUnsigned(item.value(), at.key(key));
        }
        break;
      }
      case K::CollisionChecks:  // last: the two counts it sums are read
        if (readUnsigned(member(json, f.key), at) != s.collisionChecks())
          at.fail("must equal state_checks + motion_checks (" + std::to_string(s.collisionChecks()) + ")");
        break;
    }
  }
  return s;
}

}  // namespace pmdplan
