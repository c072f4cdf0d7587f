#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

std::string plannerStatusName(PlannerStatus status) {
  switch (status) {
    case PlannerStatus::NotRun:
      return "not_run";
    case PlannerStatus::Solved:
      return "solved";
    case PlannerStatus::SampleLimit:
      return "sample_limit";
    case PlannerStatus::TimeLimit:
      return "time_limit";
    case PlannerStatus::InvalidStart:
      return "invalid_start";
    case PlannerStatus::InvalidGoal:
      return "invalid_goal";
  }
  return "unknown";
}

std::optional<PlannerStatus> parsePlannerStatus(const std::string& name) {
  for (const PlannerStatus status : {PlannerStatus::NotRun, PlannerStatus::Solved, PlannerStatus::SampleLimit,
                                     PlannerStatus::TimeLimit, PlannerStatus::InvalidStart, PlannerStatus::InvalidGoal})
    if (plannerStatusName(status) == name) return status;
  return std::nullopt;
}

}  // namespace pmdplan
