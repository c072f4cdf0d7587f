#include "pmdplan/io/files/path_file_validation.hpp"

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/files/path_validation_json.hpp"

namespace pmdplan {

PathJudgement validateTaskPath(const Task& task, const std::vector<Configuration>& points, const PathPhases& phases,
                               double toleranceMm) {
  checkMotionToleranceMm(toleranceMm);
  PathJudgement judgement;
  judgement.phases = phases;
  judgement.toleranceMm = toleranceMm;
  judgement.pointCount = points.size();
  ExactCollisionChecker checker(task);
  SegmentChecker segments(checker, *task.robot, toleranceMm / 1000.0);
  judgement.validation = GraspRule(task).validatePath(checker, segments, points, phases);
  return judgement;
}

PathJudgement validatePathFile(const Task& task, const std::filesystem::path& file, double toleranceMm) {
  checkMotionToleranceMm(toleranceMm);  // a bad tolerance before the file is read
  const PathFile read = readPathFile(file);
  if (read.jointNames != task.robot->activeJointNames())
    throw InputError(file.string(), "joint_names",
                     "the path's joints do not match the active joints of robot '" + task.robot->name() + "'");
  try {
    return validateTaskPath(task, read.points, PathPhases{read.closingFrom}, toleranceMm);
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError(file.string(), e.field(), e.message());  // the work bound (checkValidationWork) names the file
  }
}

nlohmann::ordered_json pathJudgementJson(const PathJudgement& judgement) {
  return pathValidationJson(judgement.validation, judgement.phases, judgement.toleranceMm);
}

}  // namespace pmdplan
