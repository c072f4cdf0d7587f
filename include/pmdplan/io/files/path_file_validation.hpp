#pragma once
// The independent check of a path against a task, as one service for every front end (`pmdplan
// validate`, Python's pmdplan.validate): the exact checker at a motion tolerance, judged by the
// grasp rule with the path's phases (GraspRule::validatePath, collision/grasp_rule.hpp). From a
// path file (its joints must be the task robot's active joints, its phases count) or from points.
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/collision/path_validation.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

/// A path judged against a task: the verdict and what it was judged by.
struct PathJudgement {
  PathValidation validation;
  PathPhases phases;           ///< the phases it was judged in (the file's, or the caller's)
  double toleranceMm = 1.0;    ///< the motion tolerance of the segment checks
  std::size_t pointCount = 0;  ///< the path's points
};

/// Judges `points` with `phases`. Throws InputError for a tolerance out of range (field
/// "--tolerance-mm", checkMotionToleranceMm), for a path needing more than kMaxValidationStates
/// states (field "points", no file), and StopRequested when the caller asks to stop.
PathJudgement validateTaskPath(const Task& task, const std::vector<Configuration>& points, const PathPhases& phases,
                               double toleranceMm);

/// Reads `file` (readPathFile's errors), checks its joints are the active joints of the task's
/// robot (InputError naming `file` and "joint_names") and judges its points with its phases. Every
/// InputError about the path names `file`.
PathJudgement validatePathFile(const Task& task, const std::filesystem::path& file, double toleranceMm);

/// `pmdplan validate --json`'s document (and pmdplan.validate's dict): pathValidationJson of the
/// judgement (path_validation_json.hpp).
nlohmann::ordered_json pathJudgementJson(const PathJudgement& judgement);

}  // namespace pmdplan
