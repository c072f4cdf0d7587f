// `pmdplan plan can_on_table --trajectory` and `pmdplan time`: the written trajectory keeps every
// joint within the robot's velocity and acceleration limits at a 1 ms resampling, and is
// collision-free at the checker's tolerance — the timed path rebuilt from the same path file and
// settings is checked everywhere (lines and blends) with the exact checker, states no farther apart
// than 1 mm of motion of any point of the robot.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/files/trajectory_file.hpp"
#include "pmdplan/trajectory/joint_motion_limits.hpp"
#include "pmdplan/trajectory/timed_path_inspection.hpp"
#include "pmdplan/world/task.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::contents;
using test::quoted;
using test::runCli;

TEST(TrajectoryCli, PlanWritesATimedTrajectoryWithinTheLimitsAndFreeOfCollision) {
  test::TempDir dir;
  const auto path = dir.path() / "can_on_table.path.json";
  const auto plan = runCli("plan can_on_table --seed 1 -o " + quoted(path) + " --trajectory");
  ASSERT_EQ(plan.exitCode, 0) << plan.out << plan.err;
  const auto trajectoryPath = dir.path() / "can_on_table.trajectory.json";
  ASSERT_TRUE(std::filesystem::exists(trajectoryPath)) << plan.out;
  EXPECT_NE(plan.out.find("trajectory:"), std::string::npos) << plan.out;
  const TrajectoryFile file = parseTrajectoryFile(contents(trajectoryPath), trajectoryPath.string());
  const Task task = loadTaskByName("can_on_table");
  const auto limits = jointMotionLimits(*task.robot);
  ASSERT_EQ(file.trajectory.jointNames, task.robot->activeJointNames());
  const auto& points = file.trajectory.points;
  EXPECT_LT((points.front().position - task.start).norm(), 1e-9);
  EXPECT_LT((points.back().position - task.goal).norm(), 1e-9);
  for (const TimedState& point : points)
    for (std::size_t j = 0; j < limits.size(); ++j) {
      EXPECT_LE(std::abs(point.velocity[static_cast<Eigen::Index>(j)]), limits[j].velocity * (1.0 + 1e-4))
          << limits[j].name;
      EXPECT_LE(std::abs(point.acceleration[static_cast<Eigen::Index>(j)]), limits[j].acceleration * (1.0 + 5e-3))
          << limits[j].name;
    }
  // The CSV holds the same samples.
  const std::string csv = contents(dir.path() / "can_on_table.trajectory.csv");
  EXPECT_EQ(csv.substr(0, 29), "time_from_start,tx90_joint_1,");
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), points.size() + 1);

  // Rebuilt from the path file with the blend tolerance the file records: 1 ms resampling within
  // the limits, and every state of the timed path free at 1 mm.
  const PathFile pathFile = readPathFile(path);
  TimingSettings settings;
  settings.blendTolerance = file.blendTolerance;
  const TimedPath timed(pathFile.points, limits, settings);
  EXPECT_NEAR(timed.duration(), points.back().time, 1e-9);
  for (double t = 0.0; t <= timed.duration(); t += 0.001) {
    const TimedState state = timed.at(t);
    for (std::size_t j = 0; j < limits.size(); ++j) {
      ASSERT_LE(std::abs(state.velocity[static_cast<Eigen::Index>(j)]), limits[j].velocity * (1.0 + 1e-4)) << t;
      ASSERT_LE(std::abs(state.acceleration[static_cast<Eigen::Index>(j)]), limits[j].acceleration * (1.0 + 5e-3)) << t;
    }
  }
  ExactCollisionChecker exact(task);
  const TimedPathInspection inspection = inspectTimedPath(timed, exact, SweptDistanceBound(*task.robot), 0.001);
  EXPECT_TRUE(inspection.free);
  EXPECT_GT(inspection.statesChecked, 100);
  std::printf(
      "can_on_table seed 1: %.3f s, %zu points, blend tolerance %g, %ld states checked with the exact checker\n",
      timed.duration(), points.size(), file.blendTolerance, inspection.statesChecked);
}

TEST(TrajectoryCli, TimeWritesTheSameTrajectoryAsPlanAndRejectsBadOptions) {
  test::TempDir dir;
  const auto path = dir.path() / "p.path.json";
  ASSERT_EQ(runCli("plan can_on_table --seed 2 -o " + quoted(path) + " --trajectory " + quoted(dir.path() / "a.json"))
                .exitCode,
            0);
  const auto timed = runCli("time " + quoted(path) + " -o " + quoted(dir.path() / "b.json"));
  ASSERT_EQ(timed.exitCode, 0) << timed.out << timed.err;
  EXPECT_EQ(contents(dir.path() / "a.json"), contents(dir.path() / "b.json"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "b.csv"));
  const auto slower = runCli("time " + quoted(path) + " --velocity-scale 0.5 -o " + quoted(dir.path() / "c.json"));
  ASSERT_EQ(slower.exitCode, 0) << slower.err;
  const auto a = nlohmann::json::parse(contents(dir.path() / "a.json"));
  const auto c = nlohmann::json::parse(contents(dir.path() / "c.json"));
  EXPECT_GT(c["duration"].get<double>(), a["duration"].get<double>());
  const auto bad = runCli("time " + quoted(path) + " --blend-tolerance -1");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--blend-tolerance"), std::string::npos) << bad.err;
  const auto limits = dir.write("limits.yaml", "joint_limits:\n  tx90_joint_1: {max_acceleration: -3}\n");
  const auto badLimits = runCli("time " + quoted(path) + " --joint-limits " + quoted(limits));
  EXPECT_EQ(badLimits.exitCode, 2);
  EXPECT_NE(badLimits.err.find("joint_limits.tx90_joint_1.max_acceleration"), std::string::npos) << badLimits.err;
}

}  // namespace
}  // namespace pmdplan
