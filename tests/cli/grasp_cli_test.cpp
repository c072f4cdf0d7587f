// Grasps as goals through the real binary (docs/grasp_goals.md): a task whose goal hand sinks
// 1.5 mm into its target plans as approach then closing, the path file marks both phases,
// `validate` accepts it, `check` reports the penetration depth; a goal touching another obstacle
// is refused with exit code 2 and the pair named, and `check` says so beforehand. One grasp rule
// everywhere (grasp_rule.hpp): `validate` and the viewer data judge a grasp path alike (the
// closing's hand-target contact shown as allowed contact), `bench` plans grasp goals with our
// planners and OMPL's and validates every run, and the page draws it (ViewerBrowser).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "pmdplan/core/data_directory.hpp"
#include "support/grasp_task.hpp"
#include "support/run_cli.hpp"
#include "viewer_document.hpp"

namespace pmdplan::grasp_cli {
namespace {

using test::quoted;
using test::runCli;

/// can_on_table's text with the goal can widened (test::graspedCanRadius) and `target` named.
std::string graspTaskText(const std::string& target) {
  std::string text = test::contents(dataDirectory() / "scenes" / "can_on_table.yaml");
  char radius[64];
  std::snprintf(radius, sizeof radius, "radius: %.9f", test::graspedCanRadius(0.0015));
  const std::string can = "{name: goal_can, cylinder: {radius: 0.0317";
  const auto at = text.find(can);
  EXPECT_NE(at, std::string::npos);
  text.replace(at + can.size() - std::string("radius: 0.0317").size(), std::string("radius: 0.0317").size(), radius);
  const auto targetAt = text.find("target: goal_can");
  EXPECT_NE(targetAt, std::string::npos);
  text.replace(targetAt, std::string("target: goal_can").size(), target.empty() ? "" : "target: " + target);
  return text;
}

std::filesystem::path writeGraspTask(const test::TempDir& dir, const std::string& target) {
  return dir.write("grasp_" + target + ".yaml", graspTaskText(target));
}

/// The grasp task with a sleeve, an obstacle that is not the target, 0.5 mm inside the goal can's
/// surface: the closing hand touches it as it closes onto the can.
std::filesystem::path writeSleevedGraspTask(const test::TempDir& dir) {
  std::string text = graspTaskText("goal_can");
  char sleeve[160];
  std::snprintf(sleeve, sizeof sleeve,
                "obstacles:\n  - {name: sleeve, cylinder: {radius: %.9f, length: 0.1}, xyz: [-0.47, 1.10, 0.56]}",
                test::graspedCanRadius(0.0015) - 0.0005);
  text.replace(text.find("obstacles:"), std::string("obstacles:").size(), sleeve);
  return dir.write("sleeved.yaml", text);
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

/// A grasp path planned once for the tests below: the task file and the path file.
class GraspPathCli : public ::testing::Test {
 protected:
  void SetUp() override {
    task_ = writeGraspTask(dir_, "goal_can");
    path_ = dir_.path() / "grasp.path.json";
    const auto plan = runCli(dir_, "plan " + quoted(task_) + " --seed 1 -o " + quoted(path_));
    ASSERT_EQ(plan.exitCode, 0) << plan.err << plan.out;
  }
  /// `validate --json` of the path against `task`, and the viewer data of the same path and task.
  std::pair<nlohmann::json, nlohmann::json> judge(const std::filesystem::path& task, int expectedExit) {
    const auto validate = runCli(dir_, "validate " + quoted(task) + " " + quoted(path_) + " --json");
    EXPECT_EQ(validate.exitCode, expectedExit) << validate.out << validate.err;
    const auto folder = dir_.path() / (task.stem().string() + "-viewer");
    const auto view = runCli(dir_, "view " + quoted(path_) + " --task " + quoted(task) + " --out " + quoted(folder));
    EXPECT_EQ(view.exitCode, 0) << view.err;
    return {nlohmann::json::parse(validate.out), test::viewerDocument(folder)["path"]};
  }
  test::TempDir dir_;
  std::filesystem::path task_, path_;
};

TEST_F(GraspPathCli, ValidateAndTheViewerDataJudgeAGraspPathAlikeWithItsContactAllowed) {
  const auto [validated, path] = judge(task_, 0);
  EXPECT_TRUE(validated["valid"].get<bool>());
  EXPECT_EQ(path["validation"], validated) << "the viewer's verdict is validate's, word for word";

  const std::size_t states = path["states"].size();
  ASSERT_EQ(path["contact_links"].size(), states);
  const int pregrasp = path["closing_from_state"].get<int>();
  EXPECT_EQ(pregrasp, path["waypoint_states"][validated["closing_from"].get<std::size_t>()].get<int>());
  std::set<std::string> contact;
  for (std::size_t i = 0; i < states; ++i) {
    EXPECT_TRUE(path["colliding_links"][i].empty()) << "state " << i << ": allowed contact drawn as a collision";
    EXPECT_GT(path["clearance"][i].get<double>(), 0.0) << "state " << i << ": the clearance counts allowed contact";
    if (static_cast<int>(i) <= pregrasp) {
      EXPECT_TRUE(path["contact_links"][i].empty()) << "state " << i;
    }
    for (const auto& link : path["contact_links"][i]) contact.insert(link.get<std::string>());
  }
  EXPECT_FALSE(path["contact_links"][states - 1].empty()) << "the goal grasps the can";
  EXPECT_TRUE(contact.count("thumb_proximal_link")) << "the hand links touching the can at the goal";
  // While closing, the clearance is from the other obstacles: far more than the pre-grasp's 5 mm from the can.
  EXPECT_GT(path["clearance"][states - 1].get<double>(), 0.01);
}

TEST_F(GraspPathCli, AClosingThatTouchesAnotherObstacleIsInvalidForValidateAndTheViewerData) {
  const auto [validated, path] = judge(writeSleevedGraspTask(dir_), 1);
  EXPECT_FALSE(validated["valid"].get<bool>());
  ASSERT_FALSE(validated["problems"].empty());
  const std::string problem = validated["problems"][0].get<std::string>();
  EXPECT_NE(problem.find("closing"), std::string::npos) << problem;
  EXPECT_NE(problem.find("- sleeve"), std::string::npos) << problem;
  EXPECT_EQ(problem.find("goal_can"), std::string::npos) << "the target itself is allowed while closing: " << problem;
  EXPECT_EQ(path["validation"], validated);
  // The page draws the closing's sleeve contact as a collision, the can contact as allowed contact.
  const int pregrasp = path["closing_from_state"].get<int>();
  bool collides = false;
  for (std::size_t i = 0; i < path["states"].size(); ++i) {
    if (path["colliding_links"][i].empty()) continue;
    EXPECT_GT(static_cast<int>(i), pregrasp) << "the approach touches nothing";
    EXPECT_LE(path["clearance"][i].get<double>(), 0.0);
    EXPECT_GT(path["clearance"][i].get<double>(), -0.01) << "a penetration depth, not FCL's -1 m";
    collides = true;
  }
  EXPECT_TRUE(collides);
}

TEST(GraspCli, CheckSaysWhenPlanWillRefuseTheGoalAndWhy) {
  test::TempDir dir;
  const auto grasp = runCli(dir, "check " + quoted(writeGraspTask(dir, "goal_can")) + " --json");
  ASSERT_EQ(grasp.exitCode, 0) << grasp.out << grasp.err;
  const auto accepted = nlohmann::json::parse(grasp.out);
  EXPECT_TRUE(accepted["plan"]["accepts"].get<bool>());
  EXPECT_TRUE(accepted["goal"]["pregrasp"]["derived"].get<bool>());
  EXPECT_GE(accepted["goal"]["pregrasp"]["clearance_mm"].get<double>(), 5.0);

  // Hand links in goal_can, but the task's target is obstacle_can: plan refuses (exit 2), check says why (exit 1).
  const auto other = writeGraspTask(dir, "obstacle_can");
  const auto text = runCli(dir, "check " + quoted(other));
  EXPECT_EQ(text.exitCode, 1) << text.out << text.err;
  EXPECT_NE(text.out.find("plan will refuse the task's goal: the goal configuration is in collision: "),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("thumb_proximal_link - goal_can"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("only the target 'obstacle_can'"), std::string::npos) << text.out;
  const auto json = runCli(dir, "check " + quoted(other) + " --json");
  EXPECT_EQ(json.exitCode, 1) << json.err;
  const auto refused = nlohmann::json::parse(json.out)["plan"];
  EXPECT_FALSE(refused["accepts"].get<bool>());
  ASSERT_EQ(refused["refusals"].size(), 1u);
  EXPECT_EQ(refused["refusals"][0]["field"], "goal");
  ASSERT_FALSE(refused["refusals"][0]["pairs"].empty());
  for (const auto& pair : refused["refusals"][0]["pairs"]) EXPECT_EQ(pair[1], "goal_can") << pair;
  // plan's own message is check's reason.
  const auto plan = runCli(dir, "plan " + quoted(other) + " -o " + quoted(dir.path() / "p.json"));
  EXPECT_EQ(plan.exitCode, 2);
  EXPECT_NE(plan.err.find(refused["refusals"][0]["reason"].get<std::string>()), std::string::npos) << plan.err;

  // No target at all: no contact is a grasp.
  const auto untargeted = runCli(dir, "check " + quoted(writeGraspTask(dir, "")));
  EXPECT_EQ(untargeted.exitCode, 1) << untargeted.out << untargeted.err;
  EXPECT_NE(untargeted.out.find("the task names none"), std::string::npos) << untargeted.out;
}

/// The CSV's rows as fields (no quoted commas in the columns read here: task, planner, solved, valid).
std::vector<std::vector<std::string>> csvRows(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back(1);
    bool quoted = false;
    for (const char c : line) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted)
        rows.back().emplace_back();
      else
        rows.back().back() += c;
    }
  }
  return rows;
}

TEST(GraspCli, BenchPlansAGraspGoalWithOurPlannersAndOmplsAndValidatesEveryRun) {
  test::TempDir dir;
  const auto task = writeGraspTask(dir, "goal_can");
  const auto csv = dir.path() / "runs.csv", paths = dir.path() / "paths";
  const std::string planners = "pmd,pmd-connect,ompl:RRTConnect";
  const auto bench = runCli(dir, "bench " + quoted(task) + " --planners " + planners + " --require " + planners +
                                     " --runs 2 --time-limit 20 --csv " + quoted(csv) + " --paths " + quoted(paths));
  ASSERT_EQ(bench.exitCode, 0) << bench.out << bench.err;
  const auto rows = csvRows(test::contents(csv));
  ASSERT_EQ(rows.size(), 7u) << test::contents(csv);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), name) - rows[0].begin());
  };
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r][column("solved")], "1") << rows[r][column("planner")];
    EXPECT_EQ(rows[r][column("valid")], "1") << rows[r][column("planner")] << ": " << rows[r][column("failure")];
  }
  // Every run's path is a grasp path, approach then closing, and validate takes it as bench did.
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(paths)) {
    ++files;
    const auto file = nlohmann::json::parse(test::contents(entry.path()));
    ASSERT_TRUE(file.contains("phases")) << entry.path();
    const std::size_t last = file["points"].size() - 1;
    EXPECT_EQ(file["phases"]["closing"], nlohmann::json::array({last - 1, last})) << entry.path();
    const auto validate = runCli(dir, "validate " + quoted(task) + " " + quoted(entry.path()));
    EXPECT_EQ(validate.exitCode, 0) << validate.out;
  }
  EXPECT_EQ(files, 6u);
}

using test::kBuildDirectory;
using test::kSourceTree;

TEST(ViewerBrowser, DrawsAGraspsClosingContactAsAllowedContactAndAnotherObstacleAsACollision) {
  ASSERT_TRUE(std::filesystem::exists(kSourceTree / "viewer" / "node_modules" / "playwright-core"))
      << "viewer/node_modules is missing: run scripts/install-deps (npm ci in viewer/)";
  // Kept in the build directory, for a person to look at after the run.
  const auto work = kBuildDirectory / "test-output" / "grasp-viewer";
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  const test::TempDir dir;
  const auto task = writeGraspTask(dir, "goal_can"), sleeved = writeSleevedGraspTask(dir);
  const auto path = work / "grasp.path.json";
  const auto plan = runCli("plan " + quoted(task) + " --seed 1 -o " + quoted(path));
  ASSERT_EQ(plan.exitCode, 0) << plan.out << plan.err;
  const std::string command = "node " + quoted(kSourceTree / "viewer" / "test" / "grasp_browser_test.mjs") + " --cli " +
                              quoted(PMDPLAN_CLI_PATH) + " --path " + quoted(path) + " --task " + quoted(task) +
                              " --sleeved-task " + quoted(sleeved) + " --work " + quoted(work) + " 2>&1";
  std::cout << "$ " << command << std::endl;
  const int status = std::system(command.c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0) << "see the output above";
  EXPECT_TRUE(std::filesystem::is_regular_file(work / "viewer-grasp.png"));
}

}  // namespace
}  // namespace pmdplan::grasp_cli
