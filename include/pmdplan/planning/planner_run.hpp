#pragma once
// What one run of a PMD planner (PmdRoadmapPlanner, LazyPmdPlanner, PmdConnectPlanner) keeps
// besides its roadmap: the problem check before it, the clock and the deadline during it, and the
// statistics it closes with (the smoothed path's size and lengths, the times, the motion checks).
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

/// Throws std::invalid_argument ("<planner>: the start has ...") unless c_ini and c_goal both have
/// the space's size and lie within its limits.
void checkStartAndGoal(const PlanningSpace& space, const Configuration& start, const Configuration& goal,
                       const std::string& planner);

class PlannerRun {
 public:
  /// Starts the clock; a finite time limit (seconds) sets the deadline.
  void begin(double timeLimit, const MotionValidator& motionValidator);
  /// The deadline has passed, or the caller asked to stop (core/stop_request.hpp).
  bool timeIsUp() const;
  double elapsedSeconds() const;

  /// The path the search found, smoothed if asked (Sect. 5.3); records the planning time, the
  /// smoothing time and the path's size and length before and after. The smoothing keeps to the
  /// run's deadline too: past it, only edges already checked are used (path_smoothing.hpp), so a
  /// time limit bounds the whole call.
  std::vector<Configuration> finishPath(const std::vector<Configuration>& found, const PlanningSpace& space,
                                        MotionValidator& motionValidator, bool smooth,
                                        PlanningStatistics& statistics) const;
  /// Records the end: the status, the planning time (finishPath did it for a solved run) and the
  /// motion checks since begin().
  void end(PlannerStatus status, const MotionValidator& motionValidator, PlanningStatistics& statistics) const;

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point began_{};
  std::optional<Clock::time_point> deadline_;
  std::size_t motionChecksAtStart_ = 0;
};

}  // namespace pmdplan
