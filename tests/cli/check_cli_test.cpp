#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::runCli;

TEST(CheckCli, ReportsStartGoalAndTheStraightSegmentAsJson) {
  const auto result = runCli("check can_on_table --json");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["task"], "can_on_table");
  for (const char* end : {"start", "goal"}) {
    EXPECT_TRUE(json[end]["valid"].get<bool>());
    EXPECT_TRUE(json[end]["collisions"].empty());
    EXPECT_EQ(json[end]["palm_position"].size(), 3u);
    EXPECT_EQ(json[end]["palm_z_axis"].size(), 3u);
  }
  EXPECT_NEAR(json["goal"]["palm_position"][0].get<double>(), -0.367, 0.005);
  const auto& line = json["straight_line"];
  EXPECT_FALSE(line["free"].get<bool>());
  EXPECT_GT(line["first_collision"].get<double>(), 0.0);
  EXPECT_LT(line["first_collision"].get<double>(), 1.0);
  ASSERT_FALSE(line["collisions"].empty());
  EXPECT_EQ(line["collisions"][0].size(), 2u);
  // Nothing in the task makes plan refuse it (grasp_cli_test.cpp has the refusals).
  EXPECT_TRUE(json["plan"]["accepts"].get<bool>());
  EXPECT_TRUE(json["plan"]["refusals"].empty());
  EXPECT_FALSE(json["goal"].contains("grasp")) << "the published goal touches nothing";
}

TEST(CheckCli, TheDefaultTaskIsCanOnTableInPlainText) {
  const auto result = runCli("check");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("task can_on_table"), std::string::npos);
  EXPECT_NE(result.out.find("straight segment start -> goal: in collision"), std::string::npos);
  EXPECT_NE(result.out.find("plan will take the task\n"), std::string::npos) << result.out;
}

TEST(CheckCli, BadInputEndsWithOneClearMessageAndExitCodeTwo) {
  test::TempDir dir;
  const auto bad = dir.write("bad.yaml", "name: bad\nrobot: sah_tx90\ncolour: red\n");
  for (const auto& [arguments, expected] :
       std::vector<std::pair<std::string, std::string>>{{"check no_such_task", "no_such_task"},
                                                        {"check '" + bad.string() + "'", bad.string()},
                                                        {"check can_on_table --tolerance-mm -1", "--tolerance-mm"},
                                                        {"check can_on_table --opening-step 0", "--opening-step"}}) {
    const auto result = runCli(arguments);
    EXPECT_EQ(result.exitCode, 2) << arguments;
    EXPECT_NE(result.err.find("pmdplan: error: "), std::string::npos) << result.err;
    EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << "one message: " << result.err;
    EXPECT_TRUE(result.out.empty());
  }
}

TEST(CheckCli, AMalformedRobotFileIsABadInputNamingTheFile) {
  test::TempDir dir;
  dir.write("robot.urdf", "<robot name=\"r\">\n  <link name=\"a\">\n</robot>\n");
  const auto task = dir.write("task.yaml", "name: t\nrobot: robot.urdf\nstart: {joints: {}}\ngoal: {joints: {}}\n");
  const auto result = runCli("check '" + task.string() + "'");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("robot.urdf"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("line"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace pmdplan
