// Grasps as goals through the real binary (docs/grasp_goals.md): a task whose goal hand sinks
// 1.5 mm into its target plans as approach then closing, the path file marks both phases,
// `validate` accepts it, `check` reports the penetration depth; a goal touching another obstacle
// is refused with exit code 2 and the pair named.
#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "pmdplan/core/data_directory.hpp"
#include "support/grasp_task.hpp"
#include "support/run_cli.hpp"

namespace pmdplan {
namespace {

using test::quoted;
using test::runCli;

/// can_on_table's file with the goal can widened (test::graspedCanRadius) and `target` named.
std::filesystem::path writeGraspTask(const test::TempDir& dir, const std::string& target) {
  std::string text = test::contents(dataDirectory() / "scenes" / "can_on_table.yaml");
  char radius[64];
  std::snprintf(radius, sizeof radius, "radius: %.9f", test::graspedCanRadius(0.0015));
  const std::string can = "{name: goal_can, cylinder: {radius: 0.0317";
  const auto at = text.find(can);
  EXPECT_NE(at, std::string::npos);
  text.replace(at + can.size() - std::string("radius: 0.0317").size(), std::string("radius: 0.0317").size(), radius);
  const auto targetAt = text.find("target: goal_can");
  EXPECT_NE(targetAt, std::string::npos);
  text.replace(targetAt, std::string("target: goal_can").size(), "target: " + target);
  return dir.write("grasp_" + target + ".yaml", text);
}

TEST(GraspCli, AGraspGoalPlansAsApproachThenClosingAndValidates) {
  test::TempDir dir;
  const auto task = writeGraspTask(dir, "goal_can");
  const auto path = dir.path() / "grasp.path.json";

  const auto check = runCli(dir, "check " + quoted(task) + " --json");
  ASSERT_EQ(check.exitCode, 0) << check.err;
  const auto checked = nlohmann::json::parse(check.out);
  EXPECT_GT(checked["start"]["clearance_mm"].get<double>(), 0.0);
  EXPECT_NEAR(checked["goal"]["clearance_mm"].get<double>(), -1.5, 0.2) << "the penetration depth in mm";
  EXPECT_EQ(checked["goal"]["nearest"][1], "goal_can");
  EXPECT_EQ(checked["goal"]["grasp"], "goal_can");
  const auto checkText = runCli(dir, "check " + quoted(task));
  EXPECT_NE(checkText.out.find("penetration 1."), std::string::npos) << checkText.out;
  EXPECT_NE(checkText.out.find("grasps the target goal_can"), std::string::npos) << checkText.out;

  const auto plan = runCli(dir, "plan " + quoted(task) + " --seed 1 -o " + quoted(path));
  ASSERT_EQ(plan.exitCode, 0) << plan.err << plan.out;
  EXPECT_NE(plan.out.find("then closing"), std::string::npos) << plan.out;
  const auto file = nlohmann::json::parse(test::contents(path));
  ASSERT_TRUE(file.contains("phases"));
  const std::size_t last = file["points"].size() - 1;
  EXPECT_EQ(file["phases"]["approach"], nlohmann::json::array({0, last - 1}));
  EXPECT_EQ(file["phases"]["closing"], nlohmann::json::array({last - 1, last}));

  const auto validate = runCli(dir, "validate " + quoted(task) + " " + quoted(path) + " --json");
  ASSERT_EQ(validate.exitCode, 0) << validate.out << validate.err;
  const auto validated = nlohmann::json::parse(validate.out);
  EXPECT_TRUE(validated["valid"].get<bool>());
  EXPECT_EQ(validated["closing_from"], last - 1);

  // The same points without the phases: the closing touches the target, and nothing allows it.
  auto unmarked = file;
  unmarked.erase("phases");
  const auto unmarkedPath = dir.write("unmarked.path.json", unmarked.dump());
  const auto rejected = runCli(dir, "validate " + quoted(task) + " " + quoted(unmarkedPath));
  EXPECT_EQ(rejected.exitCode, 1) << rejected.out << rejected.err;
  EXPECT_NE(rejected.out.find("goal_can"), std::string::npos) << rejected.out;
}

TEST(GraspCli, AGoalTouchingAnObstacleThatIsNotTheTargetIsRefusedWithThePairNamed) {
  test::TempDir dir;
  const auto task = writeGraspTask(dir, "obstacle_can");
  const auto plan = runCli(dir, "plan " + quoted(task) + " --seed 1 -o " + quoted(dir.path() / "p.json"));
  EXPECT_EQ(plan.exitCode, 2) << plan.out << plan.err;
  EXPECT_NE(plan.err.find(task.string()), std::string::npos) << plan.err;
  EXPECT_NE(plan.err.find("goal"), std::string::npos) << plan.err;
  EXPECT_NE(plan.err.find("_link - goal_can"), std::string::npos) << plan.err;
  EXPECT_NE(plan.err.find("'obstacle_can'"), std::string::npos) << plan.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "p.json"));
}

}  // namespace
}  // namespace pmdplan
