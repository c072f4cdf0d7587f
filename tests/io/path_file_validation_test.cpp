// validatePathFile / validateTaskPath (io/files/path_file_validation.hpp): the one check of a path
// behind `pmdplan validate` and pmdplan.validate — a file is judged as its points with its phases,
// and what is wrong with the path names the file.
#include "pmdplan/io/files/path_file_validation.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/planning/grasp_approach.hpp"
#include "support/grasp_task.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using ::testing::HasSubstr;

/// A grasp task starting at its pre-grasp: the path (pre-grasp, pre-grasp, goal) with its closing
/// from point 1 is a standing approach, then the closing.
Task closingOnlyTask() {
  Task task = test::graspingTask(0.0015);
  ExactCollisionChecker checker(task);
  const auto approach = graspApproach(task, checker, 0.001);
  if (!approach) throw std::runtime_error("the grasp task has no pre-grasp");
  task.start = approach->pregrasp;
  return task;
}

std::filesystem::path writePath(const test::TempDir& dir, const Task& task, const std::vector<Configuration>& points,
                                std::optional<std::size_t> closingFrom, const std::string& name = "p.path.json") {
  PathFile file;
  file.task = task.name;
  file.planner = "test";
  file.jointNames = task.robot->activeJointNames();
  file.points = points;
  file.closingFrom = closingFrom;
  const auto path = dir.path() / name;
  writePathFile(path, file);
  return path;
}

class PathFileValidation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { task_ = new Task(closingOnlyTask()); }
  static void TearDownTestSuite() { delete task_; }
  static Task* task_;
  test::TempDir dir_;
};
Task* PathFileValidation::task_ = nullptr;

TEST_F(PathFileValidation, AFileIsJudgedAsItsPointsWithItsPhases) {
  const Task& task = *task_;
  const std::vector<Configuration> points{task.start, task.start, task.goal};
  const auto file = writePath(dir_, task, points, 1);
  const PathJudgement fromFile = validatePathFile(task, file, 1.0);
  const PathJudgement fromPoints = validateTaskPath(task, points, PathPhases{1}, 1.0);
  EXPECT_TRUE(fromFile.validation.valid) << fromFile.validation.problems.front();
  EXPECT_EQ(fromFile.phases.closingFrom, std::optional<std::size_t>(1));
  EXPECT_EQ(fromFile.pointCount, 3u);
  EXPECT_GT(fromFile.validation.statesChecked, 0);
  EXPECT_EQ(pathJudgementJson(fromFile), pathJudgementJson(fromPoints));
}

TEST_F(PathFileValidation, WithoutItsPhasesTheClosingCollidesWithTheTarget) {
  const Task& task = *task_;
  const auto file = writePath(dir_, task, {task.start, task.start, task.goal}, std::nullopt);
  const PathJudgement judged = validatePathFile(task, file, 1.0);
  EXPECT_FALSE(judged.validation.valid);
  ASSERT_FALSE(judged.validation.problems.empty());
  EXPECT_THAT(judged.validation.problems.front(), HasSubstr("segment 1 (1 -> 2)"));
  EXPECT_THAT(judged.validation.problems.front(), HasSubstr("goal_can"));
  const auto json = pathJudgementJson(judged);
  EXPECT_FALSE(json["valid"].get<bool>());
  EXPECT_TRUE(json["closing_from"].is_null());
  EXPECT_EQ(json["collisions"][0][1], "goal_can");
}

TEST_F(PathFileValidation, TheToleranceIsTheOneJudgedAt) {
  const Task& task = *task_;
  const std::vector<Configuration> points{task.start, task.start, task.goal};
  const PathJudgement fine = validateTaskPath(task, points, PathPhases{1}, 0.5);
  const PathJudgement coarse = validateTaskPath(task, points, PathPhases{1}, 5.0);
  EXPECT_GT(fine.validation.statesChecked, coarse.validation.statesChecked);
  EXPECT_EQ(pathJudgementJson(fine)["tolerance_mm"].get<double>(), 0.5);
  test::expectInputError([&] { validateTaskPath(task, points, PathPhases{1}, 0.0); }, "", "--tolerance-mm",
                         "expected a tolerance");
}

TEST_F(PathFileValidation, AFileOfAnotherRobotNamesTheFileAndItsJoints) {
  const Task& task = *task_;
  PathFile other;
  other.task = task.name;
  other.planner = "test";
  other.jointNames = task.robot->activeJointNames();
  std::swap(other.jointNames.front(), other.jointNames.back());
  other.points = {task.start, task.goal};
  const auto file = dir_.path() / "other.path.json";
  writePathFile(file, other);
  test::expectInputError([&] { validatePathFile(task, file, 1.0); }, file.string(), "joint_names",
                         "do not match the active joints");
}

TEST_F(PathFileValidation, APathTooLongToCheckNamesTheFile) {
  const Task whole = loadTaskByName("can_on_table");  // its start and goal are far apart
  std::vector<Configuration> points;
  for (int i = 0; i < 4000; ++i) points.push_back(i % 2 ? whole.goal : whole.start);
  const auto file = writePath(dir_, whole, points, std::nullopt, "long.path.json");
  test::expectInputError([&] { validatePathFile(whole, file, 0.01); }, file.string(), "points", "states");
  test::expectInputError([&] { validateTaskPath(whole, points, PathPhases{}, 0.01); }, "", "points", "states");
}

}  // namespace
}  // namespace pmdplan
