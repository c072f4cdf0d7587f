#include "pmdplan/planning/planner_run.hpp"

#include <cmath>
#include <stdexcept>

#include "pmdplan/core/stop_request.hpp"
#include "pmdplan/planning/path_smoothing.hpp"

namespace pmdplan {

void checkStartAndGoal(const PlanningSpace& space, const Configuration& start, const Configuration& goal,
                       const std::string& planner) {
  for (const auto& [q, which] : {std::pair{&start, "start"}, std::pair{&goal, "goal"}}) {
    if (q->size() != space.dof())
      throw std::invalid_argument(planner + ": the " + which + " has " + std::to_string(q->size()) +
                                  " values, the space " + std::to_string(space.dof()) +
                                  " joints (setStartAndGoal first)");
    if (!q->allFinite() || !space.withinLimits(*q))
      throw std::invalid_argument(planner + ": the " + which + " is outside the joint limits");
  }
}

void PlannerRun::begin(double timeLimit, const MotionValidator& motionValidator) {
  began_ = Clock::now();
  deadline_.reset();
  if (std::isfinite(timeLimit))
    deadline_ = began_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeLimit));
  motionChecksAtStart_ = motionValidator.statesChecked();
}

bool PlannerRun::timeIsUp() const {
  return (deadline_ && Clock::now() >= *deadline_) || stopRequested();  // a stop ends a run as its deadline does
}

double PlannerRun::elapsedSeconds() const { return std::chrono::duration<double>(Clock::now() - began_).count(); }

std::vector<Configuration> PlannerRun::finishPath(const std::vector<Configuration>& found, const PlanningSpace& space,
                                                  MotionValidator& motionValidator, bool smooth,
                                                  PlanningStatistics& statistics) const {
  statistics.planningTime = elapsedSeconds();
  const Clock::time_point smoothingBegan = Clock::now();
  std::vector<Configuration> path =
      smooth ? smoothPath(found, space, motionValidator, [this] { return timeIsUp(); }) : found;
  statistics.smoothingTime = std::chrono::duration<double>(Clock::now() - smoothingBegan).count();
  statistics.pathNodesBeforeSmoothing = found.size();
  statistics.pathNodes = path.size();
  statistics.pathLengthBeforeSmoothing = pathLength(found, space);
  statistics.pathLength = pathLength(path, space);
  return path;
}

void PlannerRun::end(PlannerStatus status, const MotionValidator& motionValidator,
                     PlanningStatistics& statistics) const {
  statistics.status = status;
  if (status != PlannerStatus::Solved) statistics.planningTime = elapsedSeconds();
  statistics.motionChecks = motionValidator.statesChecked() - motionChecksAtStart_;
}

}  // namespace pmdplan
