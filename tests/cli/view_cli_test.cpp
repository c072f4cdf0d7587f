// `pmdplan view`, run as the real program: the viewer folder and its data for a can_on_table
// path, byte-identical on a second run, a clear error (exit 2, the file and key) for a path that
// does not fit the robot, and the page itself in Debian's chromium (viewer/test, through node):
// ready, slider, finger joint, image, screenshot, in five parts. The browser sees a path
// `pmdplan plan` made; the data tests use the straight joint-space line from start to goal (it
// passes through the table; the viewer does not care), so they do not depend on the planner.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/synergy/synergy_projection.hpp"
#include "pmdplan/world/task.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::runCli;
using ::testing::HasSubstr;

using test::kBuildDirectory;
using test::kSourceTree;

using test::contents;
using test::quoted;

/// `waypoints` evenly spaced points from the task's start to its goal.
PathFile straightPath(const Task& task, int waypoints) {
  PathFile path;
  path.task = task.name;
  path.planner = "straight-line test path";
  path.seed = 1;
  path.jointNames = task.robot->activeJointNames();
  for (int i = 0; i < waypoints; ++i)
    path.points.push_back(task.start + (task.goal - task.start) * (static_cast<double>(i) / (waypoints - 1)));
  path.mimic = mimicRelations(*task.robot);
  return path;
}

MimicRelation& coupling(PathFile& path, const std::string& joint) {
  for (auto& relation : path.mimic)
    if (relation.joint == joint) return relation;
  throw std::logic_error("no coupling of " + joint);
}

/// viewer-data.js is `window.pmdplanViewerData = {...};`: the JSON between.
nlohmann::json viewerData(const std::filesystem::path& folder) {
  const std::string text = contents(folder / "viewer-data.js");
  const std::string prefix = "window.pmdplanViewerData = ";
  EXPECT_EQ(text.rfind(prefix, 0), 0u);
  const auto end = text.rfind(';');
  return nlohmann::json::parse(text.substr(prefix.size(), end - prefix.size()));
}

class ViewCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { task_ = new Task(loadTaskByName("can_on_table")); }
  static void TearDownTestSuite() { delete task_; }
  static const Task& task() { return *task_; }
  test::TempDir dir_;

 private:
  static Task* task_;
};
Task* ViewCli::task_ = nullptr;

TEST_F(ViewCli, WritesAFolderWithTheSceneThePathAndTheSynergyReadout) {
  const auto pathFile = dir_.path() / "can.json";
  writePathFile(pathFile, straightPath(task(), 5));
  const auto out = dir_.path() / "viewer";
  const auto result = runCli("view " + quoted(pathFile) + " --out " + quoted(out));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("index.html"));
  for (const char* file :
       {"index.html", "pmdplan-viewer.js", "viewer.css", "THIRD_PARTY_NOTICES.txt", "viewer-data.js"})
    EXPECT_TRUE(std::filesystem::is_regular_file(out / file)) << file;

  const nlohmann::json data = viewerData(out);
  EXPECT_EQ(data["format"], "pmdplan-viewer-data");
  EXPECT_EQ(data["task"]["name"], "can_on_table");
  EXPECT_EQ(data["task"]["target"], "goal_can");
  ASSERT_EQ(data["task"]["obstacles"].size(), task().obstacles.size());
  const auto& table = data["task"]["obstacles"][1];
  EXPECT_EQ(table["name"], "table");
  EXPECT_EQ(table["shape"]["type"], "box");
  EXPECT_EQ(table["shape"]["size"], nlohmann::json({0.5, 0.5, 0.5}));
  EXPECT_EQ(table["position"], nlohmann::json({-0.5, 1.15, 0.25}));
  EXPECT_EQ(data["task"]["obstacles"][2]["shape"]["type"], "cylinder");
  EXPECT_EQ(data["robot"]["joint_names"], nlohmann::json(task().robot->activeJointNames()));
  EXPECT_THAT(data["robot"]["urdf"].get<std::string>(), HasSubstr("<robot name=\"sah_tx90\">"));
  EXPECT_EQ(data["robot"]["mimic"]["index_distal"], nlohmann::json({"index_medium", 1, 0}));

  // The states: start first, goal last, every waypoint among them, at most 0.01 apart (normalised).
  const auto& states = data["path"]["states"];
  const auto& waypointStates = data["path"]["waypoint_states"];
  ASSERT_EQ(waypointStates.size(), 5u);
  EXPECT_EQ(waypointStates.front(), 0);
  EXPECT_EQ(waypointStates.back().get<std::size_t>(), states.size() - 1);
  const auto state = [&](std::size_t i) {
    Configuration q(task().robot->dof());
    for (int j = 0; j < q.size(); ++j) q[j] = states[i][static_cast<std::size_t>(j)].get<double>();
    return q;
  };
  EXPECT_EQ(state(0), task().start);
  EXPECT_TRUE(state(states.size() - 1).isApprox(task().goal, 1e-15));
  for (std::size_t i = 1; i < states.size(); ++i)
    EXPECT_LE((task().robot->normalise(state(i)) - task().robot->normalise(state(i - 1))).norm(), 0.01 + 1e-12) << i;

  // The readout of the start state is the library's projection of the start posture.
  const SynergyModel model = loadSynergyModel(defaultSynergyModelPath("sah_tx90"));
  Eigen::VectorXd posture(model.jointCount());
  for (int j = 0; j < model.jointCount(); ++j) {
    const auto& joint = model.joints[static_cast<std::size_t>(j)];
    posture[j] = joint.normalise(task().start[task().robot->activeIndex(joint.name)]);
  }
  const Eigen::VectorXd expected = synergyCoefficients(model, posture);
  const auto& readout = data["synergies"]["readout"];
  ASSERT_EQ(readout["coefficients"].size(), states.size());
  for (int k = 0; k < model.directionCount(); ++k)
    EXPECT_DOUBLE_EQ(readout["coefficients"][0][static_cast<std::size_t>(k)].get<double>(), expected[k]);
  EXPECT_DOUBLE_EQ(readout["own_axis"][0][0].get<double>(), posture[model.jointIndex("thumb_base")]);
  EXPECT_EQ(data["synergies"]["planner_directions"], 4);
}

TEST_F(ViewCli, TheSamePathGivesTheSameBytes) {
  const auto pathFile = dir_.path() / "can.json";
  writePathFile(pathFile, straightPath(task(), 3));
  for (const char* out : {"a", "b"})
    ASSERT_EQ(runCli("view " + quoted(pathFile) + " --out " + quoted(dir_.path() / out)).exitCode, 0);
  EXPECT_EQ(contents(dir_.path() / "a" / "viewer-data.js"), contents(dir_.path() / "b" / "viewer-data.js"));
}

TEST_F(ViewCli, APathThatDoesNotFitTheRobotIsOneClearErrorAndNoFolder) {
  struct Case {
    std::string name;
    std::function<void(PathFile&)> spoil;
    std::string field;
    std::string message;
  };
  const std::vector<Case> cases{
      {"renamed joint", [](PathFile& p) { p.jointNames[2] = "elbow"; }, "joint_names",
       "not joints of the robot: elbow; missing: tx90_joint_3"},
      {"joint left out",
       [](PathFile& p) {
         p.jointNames.pop_back();
         for (auto& q : p.points) q = Configuration(q.head(q.size() - 1));
       },
       "joint_names", "expected the 19 active joints of robot 'sah_tx90', found 18 names; missing: ring_medium"},
      {"outside a limit", [](PathFile& p) { p.points[1][0] = 4.0; }, "points[1].positions[0]",
       "tx90_joint_1 = 4 is outside its limits"},
      {"other coupling", [](PathFile& p) { coupling(p, "index_distal").multiplier = 0.5; }, "mimic.index_distal",
       "expected [\"index_medium\", 1, 0] as in robot 'sah_tx90', found [\"index_medium\", 0.5, 0]"},
      {"coupling left out",
       [](PathFile& p) {
         const MimicRelation gone = coupling(p, "ring_distal");  // a copy: erase must not read a moved element
         std::erase(p.mimic, gone);
       },
       "mimic", "couples joints the file leaves out: ring_distal"},
  };
  for (const Case& c : cases) {
    PathFile path = straightPath(task(), 3);
    c.spoil(path);
    const auto pathFile = dir_.path() / "bad.json";
    writePathFile(pathFile, path);
    const auto out = dir_.path() / ("viewer-" + std::to_string(&c - cases.data()));
    const auto result = runCli("view " + quoted(pathFile) + " --out " + quoted(out));
    EXPECT_EQ(result.exitCode, 2) << c.name;
    EXPECT_THAT(result.err, HasSubstr("pmdplan: error: " + pathFile.string() + ": " + c.field + ": ")) << c.name;
    EXPECT_THAT(result.err, HasSubstr(c.message)) << c.name;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.name << ": nothing is written for a bad path";
  }
}

TEST_F(ViewCli, OtherBadInputNamesItsFileAndField) {
  PathFile path = straightPath(task(), 3);
  path.task = "no_such_task";
  const auto pathFile = dir_.path() / "lost.json";
  writePathFile(pathFile, path);
  auto result = runCli("view " + quoted(pathFile) + " --out " + quoted(dir_.path() / "v"));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr(pathFile.string() + ": task: "));
  EXPECT_THAT(result.err, HasSubstr("--task"));

  const auto notJson = dir_.write("broken.json", "{\"task\": ");
  result = runCli("view " + quoted(notJson));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("pmdplan: error: " + notJson.string()));

  writePathFile(pathFile, straightPath(task(), 3));
  result = runCli("view " + quoted(pathFile) + " --out " + quoted(dir_.path() / "v") + " --serve 70000");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("--serve"));
}

/// Runs a node script of viewer/; its output goes to the test log.
int runNode(const std::string& arguments) {
  const std::string command = "node " + arguments + " 2>&1";
  std::cout << "$ " << command << std::endl;
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool viewerToolsInstalled() {
  return std::filesystem::exists(kSourceTree / "viewer" / "node_modules" / "playwright-core") &&
         std::filesystem::exists(kSourceTree / "viewer" / "node_modules" / "esbuild");
}

/// Plans can_on_table and its trajectory, then runs one part of viewer/test/viewer_browser_test.mjs
/// on them in chromium: one test per part, so that ctest runs them side by side. The screenshots
/// are kept in build/test-output/viewer/<part>/, for a person to look at after the run.
void runViewerBrowserPart(const std::string& part, const std::vector<std::string>& screenshots) {
  ASSERT_TRUE(viewerToolsInstalled()) << "viewer/node_modules is missing: run scripts/install-deps (npm ci in viewer/)";
  const auto work = kBuildDirectory / "test-output" / "viewer" / part;
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  const auto path = work / "can_on_table.path.json";
  const auto trajectory = work / "can_on_table.trajectory.json";
  const auto planned = runCli("plan can_on_table --seed 1 -o " + quoted(path) + " --trajectory " + quoted(trajectory));
  ASSERT_EQ(planned.exitCode, 0) << planned.out << planned.err;
  const int code = runNode(quoted(kSourceTree / "viewer" / "test" / "viewer_browser_test.mjs") + " --cli " +
                           quoted(PMDPLAN_CLI_PATH) + " --path " + quoted(path) + " --work " + quoted(work) +
                           " --trajectory " + quoted(trajectory) + " --part " + part);
  EXPECT_EQ(code, 0) << "see the output above";
  for (const std::string& screenshot : screenshots)
    EXPECT_TRUE(std::filesystem::is_regular_file(work / screenshot)) << screenshot;
}

TEST(ViewerBrowser, OpensThePathInChromiumAndTheSliderMovesTheHand) {
  runViewerBrowserPart("motion", {"viewer-start.png"});
}

TEST(ViewerBrowser, DrawsStartGoalPalmTraceAndObjectsKeepsTheStateInTheAddressAndOpensFromTheDisk) {
  runViewerBrowserPart("display", {"viewer-start-goal.png", "viewer-objects.png", "viewer.png"});
}

TEST(ViewerBrowser, DrawsTheStraightSegmentThroughTheCanInCollision) {
  runViewerBrowserPart("collisions", {"viewer-collision.png"});
}

TEST(ViewerBrowser, PlaysSeveralPathsInSyncAndWarnsOfAMovedGoal) {
  runViewerBrowserPart("paths", {"viewer-paths.png", "viewer-ends-warning.png"});
}

TEST(ViewerBrowser, PlaysTheTimedTrajectoryInRealTimeWithItsPlotsAndTwoInSyncByTime) {
  runViewerBrowserPart("trajectory", {"viewer-trajectory.png", "viewer-paths-timed.png"});
}

TEST(ViewerBrowser, TheCommittedBundleMatchesItsSources) {
  ASSERT_TRUE(viewerToolsInstalled()) << "viewer/node_modules is missing: run scripts/install-deps (npm ci in viewer/)";
  EXPECT_EQ(runNode(quoted(kSourceTree / "viewer" / "scripts" / "build-bundle.mjs") + " --check"), 0)
      << "rebuild it: npm --prefix viewer run build";
}

}  // namespace
}  // namespace pmdplan
